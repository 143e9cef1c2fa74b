#include "plot/canvas.hpp"

#include <cairo-svg.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/output_folder.hpp"

namespace wifislam::plot {

void set_colour(cairo_t* cr, const Colour& c, double alpha) {
  cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
}

Colour category_colour(std::int64_t index) {
  static const Colour palette[] = {{0.12, 0.47, 0.71}, {1.00, 0.50, 0.05}, {0.17, 0.63, 0.17},
                                   {0.84, 0.15, 0.16}, {0.58, 0.40, 0.74}, {0.55, 0.34, 0.29},
                                   {0.89, 0.47, 0.76}, {0.50, 0.50, 0.50}, {0.74, 0.74, 0.13},
                                   {0.09, 0.75, 0.81}};
  constexpr std::int64_t n = sizeof(palette) / sizeof(palette[0]);
  if (index >= 0 && index < n) return palette[index];
  // HSV with the golden angle: neighbouring ids get well separated hues.
  const double h = std::fmod(static_cast<double>(index) * 137.508, 360.0) / 60.0;
  const double s = 0.75, v = 0.85, c = v * s, x = c * (1 - std::abs(std::fmod(h, 2.0) - 1));
  const int sector = static_cast<int>(h);
  const double m = v - c;
  const double rgb[6][3] = {{c, x, 0}, {x, c, 0}, {0, c, x}, {0, x, c}, {x, 0, c}, {c, 0, x}};
  return {rgb[sector % 6][0] + m, rgb[sector % 6][1] + m, rgb[sector % 6][2] + m};
}

Colour viridis(double t) {
  static constexpr double kStops[5][3] = {{0.267, 0.005, 0.329},
                                          {0.231, 0.322, 0.545},
                                          {0.129, 0.569, 0.549},
                                          {0.369, 0.788, 0.384},
                                          {0.993, 0.906, 0.144}};
  t = std::clamp(t, 0.0, 1.0) * 4.0;
  const int i = std::min(static_cast<int>(t), 3);
  const double f = t - i;
  return {kStops[i][0] + f * (kStops[i + 1][0] - kStops[i][0]),
          kStops[i][1] + f * (kStops[i + 1][1] - kStops[i][1]),
          kStops[i][2] + f * (kStops[i + 1][2] - kStops[i][2])};
}

void write_figure(const std::filesystem::path& path, int width_px, int height_px,
                  const std::function<void(cairo_t*)>& draw, PixelFormat format) {
  check_file_replaceable(path);
  const bool svg = path.extension() == ".svg";
  const std::filesystem::path partial = path.string() + ".partial";
  cairo_surface_t* surface =
      svg ? cairo_svg_surface_create(partial.c_str(), width_px, height_px)
          : cairo_image_surface_create(
                format == PixelFormat::kRgb24 ? CAIRO_FORMAT_RGB24 : CAIRO_FORMAT_ARGB32, width_px,
                height_px);
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface_guard(
      surface, &cairo_surface_destroy);
  std::error_code ec;
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
    std::filesystem::remove(partial, ec);
    throw IoError(path.string() + ": cannot create drawing surface: " +
                  cairo_status_to_string(cairo_surface_status(surface)));
  }
  cairo_t* cr = cairo_create(surface);
  std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr_guard(cr, &cairo_destroy);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  draw(cr);
  cr_guard.reset();
  cairo_status_t status = CAIRO_STATUS_SUCCESS;
  if (svg) {
    cairo_surface_finish(surface);
    status = cairo_surface_status(surface);
  } else {
    status = cairo_surface_write_to_png(surface, partial.c_str());
  }
  surface_guard.reset();
  if (status != CAIRO_STATUS_SUCCESS) {
    std::filesystem::remove(partial, ec);
    throw IoError(path.string() + ": cannot write the figure: " + cairo_status_to_string(status));
  }
  std::filesystem::rename(partial, path, ec);
  if (ec) {
    std::filesystem::remove(partial, ec);
    throw IoError(path.string() + ": cannot rename the finished figure into place");
  }
}

MetricCanvas::MetricCanvas(Eigen::Vector2d lo_m, Eigen::Vector2d hi_m, double max_plan_px) {
  lo_ = lo_m - Eigen::Vector2d::Constant(0.5);
  hi_ = hi_m + Eigen::Vector2d::Constant(0.5);
  const Eigen::Vector2d extent = (hi_ - lo_).cwiseMax(1.0);
  hi_ = lo_ + extent;
  ppm_ = std::clamp(max_plan_px / std::max(extent.x(), extent.y()), 2.0, 120.0);
}

MetricCanvas MetricCanvas::exact(const Eigen::Vector2d& lo_m, const Eigen::Vector2d& hi_m,
                                 double ppm) {
  MetricCanvas canvas;
  canvas.lo_ = lo_m;
  canvas.hi_ = hi_m;
  canvas.ppm_ = ppm;
  return canvas;
}

Eigen::Vector2d MetricCanvas::px(const Eigen::Vector2d& p) const {
  return {kMarginPx + (p.x() - lo_.x()) * ppm_, kTitlePx + (hi_.y() - p.y()) * ppm_};
}

int MetricCanvas::width_px() const {
  return static_cast<int>(std::ceil(plan_right_px() + kMarginPx + kLegendPx));
}

int MetricCanvas::height_px() const {
  return static_cast<int>(std::ceil(std::max(plan_bottom_px() + kFooterPx, 360.0)));
}

void draw_text(cairo_t* cr, double x, double y, const std::string& text, double size, bool bold) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
  // show_text leaves the current point after the text; a following arc would be joined to it.
  cairo_new_path(cr);
}

void draw_polyline(cairo_t* cr, const MetricCanvas& canvas,
                   const std::vector<Eigen::Vector2d>& points_m, double width_px) {
  if (points_m.size() < 2) return;
  cairo_set_line_width(cr, width_px);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (std::size_t i = 0; i < points_m.size(); ++i) {
    const Eigen::Vector2d p = canvas.px(points_m[i]);
    i == 0 ? cairo_move_to(cr, p.x(), p.y()) : cairo_line_to(cr, p.x(), p.y());
  }
  cairo_stroke(cr);
}

void draw_segment(cairo_t* cr, const MetricCanvas& canvas, const Eigen::Vector2d& a_m,
                  const Eigen::Vector2d& b_m, double width_px) {
  const Eigen::Vector2d p = canvas.px(a_m), q = canvas.px(b_m);
  cairo_set_line_width(cr, width_px);
  cairo_move_to(cr, p.x(), p.y());
  cairo_line_to(cr, q.x(), q.y());
  cairo_stroke(cr);
}

void draw_scale_bar(cairo_t* cr, double x0, double y, double ppm, double plan_width_m,
                    const ScaleBar& style) {
  double bar_m = 1;
  for (double candidate : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0}) {
    if (candidate <= style.longest_m && candidate <= 0.25 * plan_width_m) bar_m = candidate;
  }
  const double x1 = x0 + bar_m * ppm;
  set_colour(cr, {0, 0, 0});
  cairo_set_line_width(cr, 3.0);
  cairo_move_to(cr, x0, y);
  cairo_line_to(cr, x1, y);
  cairo_stroke(cr);
  if (style.end_ticks) {
    cairo_set_line_width(cr, 1.5);
    for (double x : {x0, x1}) {
      cairo_move_to(cr, x, y - 5);
      cairo_line_to(cr, x, y + 5);
      cairo_stroke(cr);
    }
  }
  draw_text(cr, x1 + 8, y + 5, fmt::format("{:g} m", bar_m), 13);
}

void draw_scale_bar(cairo_t* cr, const MetricCanvas& canvas) {
  draw_scale_bar(cr, MetricCanvas::kMarginPx, canvas.plan_bottom_px() + 28, canvas.ppm(),
                 canvas.plan_width_m());
}

double legend_line(cairo_t* cr, double x, double y, const Colour& c, double width_px,
                   const std::string& label) {
  set_colour(cr, c);
  cairo_set_line_width(cr, width_px);
  cairo_move_to(cr, x, y - 4);
  cairo_line_to(cr, x + 24, y - 4);
  cairo_stroke(cr);
  set_colour(cr, {0, 0, 0});
  draw_text(cr, x + 32, y, label, 13);
  return y + 20;
}

double legend_dot(cairo_t* cr, double x, double y, const Colour& c, const std::string& label) {
  set_colour(cr, c);
  cairo_arc(cr, x + 12, y - 4, 5, 0, 2 * M_PI);
  cairo_fill(cr);
  set_colour(cr, {0, 0, 0});
  draw_text(cr, x + 32, y, label, 13);
  return y + 20;
}

double legend_box(cairo_t* cr, double x, double y, const Colour& c, const std::string& label) {
  set_colour(cr, c);
  cairo_rectangle(cr, x, y - 11, 22, 12);
  cairo_fill(cr);
  set_colour(cr, {0, 0, 0});
  draw_text(cr, x + 30, y, label, 13);
  return y + 20;
}

}  // namespace wifislam::plot
