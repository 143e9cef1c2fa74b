#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "eval/plots.hpp"
#include "plot/canvas.hpp"
#include "plot/line_chart.hpp"

namespace wifislam::eval {

void plot_error_along_path(const std::filesystem::path& path, const RunEvaluation& ev) {
  constexpr int kWidth = 1000, kHeight = 420;
  constexpr double left = 70, right = 30, top = 50, bottom = 60;
  double x_min = 0, x_max = 1, y_max = 0.01;
  if (!ev.path.empty()) {
    x_min = ev.path.front().path_m;
    x_max = std::max(x_min + 1e-3, ev.path.back().path_m);
  }
  for (const PathSample& s : ev.path) y_max = std::max(y_max, s.error_m);
  y_max *= 1.1;
  const double plot_w = kWidth - left - right, plot_h = kHeight - top - bottom;
  auto to_px = [&](double x, double y) {
    return Eigen::Vector2d(left + (x - x_min) / (x_max - x_min) * plot_w,
                           top + plot_h - y / y_max * plot_h);
  };
  plot::write_figure(path, kWidth, kHeight, [&](cairo_t* cr) {
    // Grid and tick labels.
    cairo_set_line_width(cr, 1.0);
    const double xs = plot::tick_step(x_max - x_min, 10), ys = plot::tick_step(y_max, 6);
    for (double x = std::ceil(x_min / xs) * xs; x <= x_max + 1e-9; x += xs) {
      const Eigen::Vector2d p = to_px(x, 0);
      plot::set_colour(cr, {0.88, 0.88, 0.88});
      cairo_move_to(cr, p.x(), top);
      cairo_line_to(cr, p.x(), top + plot_h);
      cairo_stroke(cr);
      plot::set_colour(cr, {0, 0, 0});
      plot::draw_text(cr, p.x() - 10, top + plot_h + 18, fmt::format("{:g}", x), 12);
    }
    for (double y = 0; y <= y_max + 1e-12; y += ys) {
      const Eigen::Vector2d p = to_px(x_min, y);
      plot::set_colour(cr, {0.88, 0.88, 0.88});
      cairo_move_to(cr, left, p.y());
      cairo_line_to(cr, left + plot_w, p.y());
      cairo_stroke(cr);
      plot::set_colour(cr, {0, 0, 0});
      plot::draw_text(cr, 26, p.y() + 4, fmt::format("{:.3g}", y), 12);
    }
    plot::set_colour(cr, {0, 0, 0});
    cairo_rectangle(cr, left, top, plot_w, plot_h);
    cairo_stroke(cr);
    // Loop closures (their later keyframe) as vertical ticks at the top.
    for (const ScoredLoopClosure& c : ev.loop_closure_score.closures) {
      const double at = ev.keyframe_truth[static_cast<std::size_t>(c.edge.to_keyframe)].path_m;
      const Eigen::Vector2d p = to_px(std::clamp(at, x_min, x_max), 0);
      plot::set_colour(cr, c.correct() ? plot::Colour{0.10, 0.65, 0.20}
                           : c.verdict == LoopClosureVerdict::kRightPlaceImprecise
                               ? plot::Colour{0.95, 0.60, 0.05}
                               : plot::Colour{0.90, 0.10, 0.10});
      cairo_set_line_width(cr, 2.0);
      cairo_move_to(cr, p.x(), top);
      cairo_line_to(cr, p.x(), top + 12);
      cairo_stroke(cr);
    }
    // The error.
    plot::set_colour(cr, {0.10, 0.35, 0.90});
    cairo_set_line_width(cr, 1.5);
    for (std::size_t i = 0; i < ev.path.size(); ++i) {
      const Eigen::Vector2d p = to_px(ev.path[i].path_m, ev.path[i].error_m);
      i == 0 ? cairo_move_to(cr, p.x(), p.y()) : cairo_line_to(cr, p.x(), p.y());
    }
    cairo_stroke(cr);
    // RMSE.
    const Eigen::Vector2d r = to_px(x_min, ev.ate_rmse_m);
    plot::set_colour(cr, {0.85, 0.45, 0.0});
    const double dash[] = {6.0, 4.0};
    cairo_set_dash(cr, dash, 2, 0);
    cairo_move_to(cr, left, r.y());
    cairo_line_to(cr, left + plot_w, r.y());
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
    plot::set_colour(cr, {0, 0, 0});
    plot::draw_text(cr, left, 24,
                    fmt::format("Absolute trajectory error along the path (RMSE {:.3f} m, dashed)",
                                ev.ate_rmse_m),
                    15, true);
    plot::draw_text(
        cr, left, 42,
        "ticks at the top: loop closures at their later keyframe (green correct, red false)", 11);
    plot::draw_text(cr, left + plot_w / 2 - 120, kHeight - 15, "ground-truth path length [m]", 13);
    cairo_save(cr);
    cairo_translate(cr, 16, top + plot_h / 2 + 70);
    cairo_rotate(cr, -M_PI / 2);
    plot::draw_text(cr, 0, 0, "error after alignment [m]", 13);
    cairo_restore(cr);
  });
}

}  // namespace wifislam::eval
