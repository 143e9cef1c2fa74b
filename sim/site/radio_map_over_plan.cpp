#include "sim/site/radio_map_over_plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

#include <fmt/format.h>

#include "plot/canvas.hpp"

namespace wifislam::sim::site {

namespace {

// Which cells have their centre in free space: the plan rasterised by cairo (no antialiasing,
// so a pixel is set exactly when its centre is inside), one pixel per cell.
std::vector<bool> free_space_mask(const world::FloorPlan& plan, const Eigen::Vector2d& origin_m,
                                  double resolution_m, int cols, int rows) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_A8, cols, rows);
  cairo_t* cr = cairo_create(surface);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
  cairo_scale(cr, 1.0 / resolution_m, 1.0 / resolution_m);
  cairo_translate(cr, -origin_m.x(), -origin_m.y());
  for (const auto& region : plan.free_space) {
    plot::region_path(cr, region, plot::as_is);
    cairo_fill(cr);  // region by region: overlapping regions must not cancel out
  }
  cairo_destroy(cr);
  cairo_surface_flush(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  std::vector<bool> mask(static_cast<std::size_t>(cols) * rows);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      mask[static_cast<std::size_t>(r) * cols + c] =
          data[static_cast<std::size_t>(r) * stride + c] != 0;
  cairo_surface_destroy(surface);
  return mask;
}

}  // namespace

radio_model::RadioMapArea radio_map_area(const world::FloorPlan& plan, double floor_elevation_m) {
  radio_model::RadioMapArea area;
  area.floor_elevation_m = floor_elevation_m;
  area.bounds_min_m = plan.bounds_min_m;
  area.bounds_max_m = plan.bounds_max_m;
  area.ceiling_m = plan.wall_height_m;
  if (!plan.free_space.empty()) {
    area.cells_to_compute = [&plan](const radio_model::RadioMap& grid) {
      return free_space_mask(plan, grid.origin_m, grid.resolution_m, grid.cols, grid.rows);
    };
  }
  return area;
}

radio_model::RadioMap compute_radio_map(const radio_model::PropagationModel& model,
                                        const world::FloorPlan& plan,
                                        const radio_model::RadioMapOptions& options,
                                        double floor_elevation_m) {
  return radio_model::compute_radio_map(model, radio_map_area(plan, floor_elevation_m), options);
}

void write_radio_map_png(const radio_model::RadioMap& map, const world::FloorPlan& plan,
                         const std::vector<radio_model::AccessPoint>& access_points,
                         const std::filesystem::path& path, double floor_dbm) {
  const Eigen::Vector2d extent = plan.bounds_max_m - plan.bounds_min_m;
  const double px_per_m = std::clamp(1600.0 / std::max({extent.x(), extent.y(), 1.0}), 4.0, 40.0);
  const int margin = 20, bar_w = 90;
  const int width = static_cast<int>(std::ceil(extent.x() * px_per_m)) + 2 * margin + bar_w;
  const int height = static_cast<int>(std::ceil(extent.y() * px_per_m)) + 2 * margin;

  // Colour range: from the floor to the strongest value, rounded out to 5 dB.
  float top = static_cast<float>(floor_dbm + 5.0);
  for (float v : map.rssi_dbm)
    if (std::isfinite(v)) top = std::max(top, v);
  const double hi = std::ceil(top / 5.0) * 5.0, lo = floor_dbm;

  // The grid as a small image (one pixel per cell, y flipped), scaled up with nearest filtering.
  cairo_surface_t* cells = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, map.cols, map.rows);
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> cells_guard(
      cells, &cairo_surface_destroy);
  cairo_surface_flush(cells);
  unsigned char* data = cairo_image_surface_get_data(cells);
  const int stride = cairo_image_surface_get_stride(cells);
  for (int r = 0; r < map.rows; ++r) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::size_t>(map.rows - 1 - r) *
                                                            stride);
    for (int c = 0; c < map.cols; ++c) {
      const double v = map.at(c, r);
      plot::Colour rgb{0.82, 0.82, 0.82};
      if (std::isfinite(v) && v >= lo) rgb = plot::viridis((v - lo) / (hi - lo));
      row[c] = 0xFF000000u | (static_cast<std::uint32_t>(rgb.r * 255.0 + 0.5) << 16) |
               (static_cast<std::uint32_t>(rgb.g * 255.0 + 0.5) << 8) |
               static_cast<std::uint32_t>(rgb.b * 255.0 + 0.5);
    }
  }
  cairo_surface_mark_dirty(cells);

  const auto draw = [&](cairo_t* cr) {
    // Plan coordinates: metres, y up.
    cairo_save(cr);
    cairo_translate(cr, margin, height - margin);
    cairo_scale(cr, px_per_m, -px_per_m);
    cairo_translate(cr, -plan.bounds_min_m.x(), -plan.bounds_min_m.y());
    cairo_matrix_t plan_matrix;
    cairo_get_matrix(cr, &plan_matrix);

    // Heat map clipped to free space (even-odd: holes cut out).
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
    for (const auto& region : plan.free_space) plot::region_path(cr, region, plot::as_is);
    if (plan.free_space.empty()) {
      cairo_rectangle(cr, plan.bounds_min_m.x(), plan.bounds_min_m.y(), extent.x(), extent.y());
    }
    cairo_clip(cr);
    cairo_save(cr);
    cairo_translate(cr, map.origin_m.x(), map.origin_m.y() + map.rows * map.resolution_m);
    cairo_scale(cr, map.resolution_m, -map.resolution_m);
    cairo_set_source_surface(cr, cells, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
    cairo_paint(cr);
    cairo_restore(cr);
    cairo_reset_clip(cr);

    // Walls, as one path (even-odd).
    plot::set_colour(cr, {0.15, 0.15, 0.15});
    for (const auto& region : plan.walls) plot::region_path(cr, region, plot::as_is);
    cairo_fill(cr);
    cairo_restore(cr);

    // Access points: white dots with their ids.
    for (const radio_model::AccessPoint& ap : access_points) {
      double x = ap.position_m.x(), y = ap.position_m.y();
      cairo_matrix_transform_point(&plan_matrix, &x, &y);
      const bool selected = !map.ap_id || *map.ap_id == ap.id;
      cairo_arc(cr, x, y, selected ? 5 : 3.5, 0, 2 * M_PI);
      plot::set_colour(cr, {1, 1, 1});
      cairo_fill_preserve(cr);
      plot::set_colour(cr, {selected ? 0.8 : 0.3, 0.1, 0.1});
      cairo_set_line_width(cr, 1.5);
      cairo_stroke(cr);
      plot::draw_text(cr, x + 6, y - 6, fmt::format("{}", ap.id), 11, true);
    }

    // Colour bar with dBm labels.
    const double bx = width - bar_w + 10, by = margin, bh = height - 2 * margin, bw = 18;
    for (int i = 0; i < static_cast<int>(bh); ++i) {
      plot::set_colour(cr, plot::viridis(1.0 - i / bh));
      cairo_rectangle(cr, bx, by + i, bw, 1);
      cairo_fill(cr);
    }
    plot::set_colour(cr, {0, 0, 0});
    for (double v = lo; v <= hi + 1e-9; v += 10.0) {
      const double y = by + bh * (1.0 - (v - lo) / (hi - lo));
      plot::draw_text(cr, bx + bw + 4, y + 3, fmt::format("{:.0f}", v), 10, true);
    }
    plot::draw_text(cr, bx - 4, by - 6, "dBm", 10, true);
  };
  plot::write_figure(path, width, height, draw, plot::PixelFormat::kRgb24);
}

}  // namespace wifislam::sim::site
