#include "radio_model/radio_map.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <thread>

#include <fmt/format.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/worker_pool.hpp"
#include "plot/canvas.hpp"

namespace wifislam::radio_model {

namespace {

double ap_rssi(const PropagationModel& model, std::size_t a, const RadioLink& link,
               RadioMapBand band) {
  double best = -std::numeric_limits<double>::infinity();
  std::int64_t last_khz = -1;
  for (const Bssid& b : model.access_points()[a].bssids) {
    if (band == RadioMapBand::k2_4GHz && b.band != RadioBand::k2_4GHz) continue;
    if (band == RadioMapBand::k5GHz && b.band != RadioBand::k5GHz) continue;
    if (b.frequency_khz == last_khz) continue;  // BSSIDs of one radio share its channel
    last_khz = b.frequency_khz;
    best = std::max(best, model.mean_rssi_dbm(a, b, link));
  }
  return best;
}

// Which cells have their centre in free space: the plan rasterised by cairo (no antialiasing,
// so a pixel is set exactly when its centre is inside), one pixel per cell.
std::vector<bool> free_space_mask(const sim::FloorPlan& plan, const Eigen::Vector2d& origin_m,
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

namespace {

/// An empty map over the plan at the options' resolution. Throws InvalidInputError for a
/// resolution or height out of range, or a map over the size limits.
RadioMap empty_map(const sim::FloorPlan& plan, const RadioMapOptions& options) {
  if (!(options.resolution_m > 0.0))
    throw InvalidInputError(
        fmt::format("radio map resolution must be > 0 (got {})", options.resolution_m));
  if (!(options.receiver_height_m > 0.0 && options.receiver_height_m < plan.wall_height_m)) {
    throw InvalidInputError(
        fmt::format("radio map: receiver height {} m is not between the floor and the ceiling "
                    "(0 to {} m)",
                    options.receiver_height_m, plan.wall_height_m));
  }
  RadioMap map;
  map.origin_m = plan.bounds_min_m;
  map.resolution_m = options.resolution_m;
  map.ap_id = options.ap_id;
  const Eigen::Vector2d extent = plan.bounds_max_m - plan.bounds_min_m;
  // Counted in doubles first: a tiny resolution once overflowed the int and gave a 1 x 1 map.
  const double cols = std::max(1.0, std::ceil(extent.x() / options.resolution_m));
  const double rows = std::max(1.0, std::ceil(extent.y() / options.resolution_m));
  if (cols > kRadioMapMaxSide || rows > kRadioMapMaxSide ||
      cols * rows > static_cast<double>(kRadioMapMaxCells)) {
    const double finest_m =
        std::max(std::sqrt(extent.x() * extent.y() / static_cast<double>(kRadioMapMaxCells)),
                 std::max(extent.x(), extent.y()) / kRadioMapMaxSide);
    throw InvalidInputError(fmt::format(
        "radio map: a resolution of {} m gives {:.0f} x {:.0f} cells over this {:.1f} x {:.1f} m "
        "plan; a map has at most {} million cells and {} a side, so use a resolution of at "
        "least {:.3g} m (--res)",
        options.resolution_m, cols, rows, extent.x(), extent.y(), kRadioMapMaxCells / 1'000'000,
        kRadioMapMaxSide, finest_m * 1.001));
  }
  map.cols = static_cast<int>(cols);
  map.rows = static_cast<int>(rows);
  const std::size_t cells = static_cast<std::size_t>(map.cols) * map.rows;
  map.rssi_dbm.assign(cells, std::numeric_limits<float>::quiet_NaN());
  map.best_ap_id.assign(cells, -1);
  return map;
}

/// The strongest access point at one receiver position: (RSSI, index), ties to the lowest index.
/// With `prune`, APs are tried in order of their wall-free RSSI (an upper bound) and the search
/// stops when the bound cannot beat the best so far: the same answer, fewer ray casts.
std::pair<double, std::size_t> strongest(const PropagationModel& model, const Eigen::Vector3d& rx,
                                         RadioMapBand band, std::optional<std::size_t> only,
                                         bool prune,
                                         std::vector<std::pair<double, std::size_t>>& bounds) {
  const std::size_t n = model.access_points().size();
  double best = -std::numeric_limits<double>::infinity();
  std::size_t best_index = n;
  const auto consider = [&](std::size_t a) {
    const double v = ap_rssi(model, a, model.link(a, rx), band);
    if (v > best || (v == best && a < best_index)) {
      best = v;
      best_index = a;
    }
  };
  if (only) {
    consider(*only);
  } else if (!prune) {
    for (std::size_t a = 0; a < n; ++a) consider(a);
  } else {
    bounds.clear();
    for (std::size_t a = 0; a < n; ++a)
      bounds.emplace_back(ap_rssi(model, a, model.link_without_walls(a, rx), band), a);
    std::sort(bounds.begin(), bounds.end(),
              [](const auto& x, const auto& y) { return x.first > y.first; });
    for (const auto& [bound, a] : bounds) {
      if (bound < best) break;
      consider(a);
    }
  }
  return {best, best_index};
}

}  // namespace

RadioMap compute_radio_map(const PropagationModel& model, const sim::FloorPlan& plan,
                           const RadioMapOptions& options) {
  RadioMap map = empty_map(plan, options);
  const auto& aps = model.access_points();
  if (aps.empty()) throw InvalidInputError("radio map: the scene has no access points");
  std::optional<std::size_t> only;
  if (options.ap_id) {
    only = model.index_of(*options.ap_id);
    if (!only)
      throw InvalidInputError(fmt::format("radio map: no access point with id {} (ids 0..{})",
                                          *options.ap_id, aps.size() - 1));
  }
  std::vector<bool> compute(map.rssi_dbm.size(), true);
  if (options.free_space_only && !plan.free_space.empty())
    compute = free_space_mask(plan, map.origin_m, map.resolution_m, map.cols, map.rows);
  const bool prune = options.prune && model.walls_only_attenuate();
  // Rows on worker threads; every cell depends only on its own position, so any thread count
  // gives the same map.
  parallel_for(
      clamp_thread_count(options.threads), static_cast<std::size_t>(map.rows), [&](std::size_t r) {
        std::vector<std::pair<double, std::size_t>> bounds;
        for (int c = 0; c < map.cols; ++c) {
          const std::size_t i = r * static_cast<std::size_t>(map.cols) + c;
          if (!compute[i]) continue;
          const Eigen::Vector2d xy = map.cell_center_m(c, static_cast<int>(r));
          const Eigen::Vector3d rx(xy.x(), xy.y(), options.receiver_height_m);
          const auto [best, index] = strongest(model, rx, options.band, only, prune, bounds);
          map.rssi_dbm[i] = static_cast<float>(best);
          map.best_ap_id[i] = index < aps.size() ? aps[index].id : -1;
        }
      });
  return map;
}

void write_radio_map_png(const RadioMap& map, const sim::FloorPlan& plan,
                         const std::vector<AccessPoint>& access_points,
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
    for (const AccessPoint& ap : access_points) {
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

void write_radio_map_csv(const RadioMap& map, const std::filesystem::path& path) {
  std::string text = "x_m,y_m,rssi_dbm,ap_id\n";
  for (int r = 0; r < map.rows; ++r) {
    for (int c = 0; c < map.cols; ++c) {
      const Eigen::Vector2d p = map.cell_center_m(c, r);
      const std::size_t i = static_cast<std::size_t>(r) * map.cols + c;
      if (!std::isfinite(map.rssi_dbm[i])) continue;
      fmt::format_to(std::back_inserter(text), "{:.3f},{:.3f},{:.2f},{}\n", p.x(), p.y(),
                     map.rssi_dbm[i], map.best_ap_id[i]);
    }
  }
  write_file_atomic(path, text);
}

}  // namespace wifislam::radio_model
