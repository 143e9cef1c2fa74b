#include "plot/line_chart.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace wifislam::plot {

double tick_step(double range, int target) {
  const double raw = range / std::max(1, target);
  if (!(raw > 0) || !std::isfinite(raw)) return 1.0;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (raw <= m * magnitude) return m * magnitude;
  }
  return 10 * magnitude;
}

void draw_line_chart(const std::filesystem::path& path, const LineChart& chart) {
  constexpr int kWidth = 1000, kHeight = 560;
  constexpr double left = 80, right = 250, top = 70, bottom = 64;
  const double plot_w = kWidth - left - right, plot_h = kHeight - top - bottom;

  // Ranges over every finite value, bands included.
  double x_min = std::numeric_limits<double>::infinity(), x_max = -x_min;
  double y_min = x_min, y_max = -x_min;
  bool any_missing = false;
  for (const ChartSeries& s : chart.series) {
    for (const ChartPoint& p : s.points) {
      x_min = std::min(x_min, p.x);
      x_max = std::max(x_max, p.x);
      if (!std::isfinite(p.y)) {
        any_missing = true;
        continue;
      }
      y_min = std::min({y_min, p.y, p.y_lo});
      y_max = std::max({y_max, p.y, p.y_hi});
    }
  }
  if (!chart.x_categories.empty()) {
    x_min = -0.5;
    x_max = static_cast<double>(chart.x_categories.size()) - 0.5;
  }
  if (!std::isfinite(x_min)) x_min = 0, x_max = 1;
  if (x_max - x_min < 1e-12) x_min -= 0.5, x_max += 0.5;
  if (!std::isfinite(y_min)) y_min = 0, y_max = 1;
  if (chart.y_from_zero && y_min >= 0) y_min = 0;
  if (y_max - y_min < 1e-12) y_max = y_min + (y_min == 0 ? 1.0 : std::abs(y_min) * 0.1);
  const double y_pad = 0.06 * (y_max - y_min);
  y_max += y_pad;
  if (!(chart.y_from_zero && y_min == 0)) y_min -= y_pad;

  const auto to_px = [&](double x, double y) {
    return Eigen::Vector2d(left + (x - x_min) / (x_max - x_min) * plot_w,
                           top + plot_h - (y - y_min) / (y_max - y_min) * plot_h);
  };

  write_figure(path, kWidth, kHeight, [&](cairo_t* cr) {
    cairo_set_line_width(cr, 1.0);
    // Vertical grid and x tick labels.
    std::vector<std::pair<double, std::string>> x_ticks;
    if (!chart.x_categories.empty()) {
      for (std::size_t i = 0; i < chart.x_categories.size(); ++i)
        x_ticks.emplace_back(static_cast<double>(i), chart.x_categories[i]);
    } else {
      const double xs = tick_step(x_max - x_min, 10);
      for (double x = std::ceil(x_min / xs) * xs; x <= x_max + 1e-9 * xs; x += xs)
        x_ticks.emplace_back(x, fmt::format("{:g}", std::abs(x) < 1e-12 ? 0.0 : x));
    }
    for (const auto& [x, label] : x_ticks) {
      const Eigen::Vector2d p = to_px(x, y_min);
      set_colour(cr, {0.88, 0.88, 0.88});
      cairo_move_to(cr, p.x(), top);
      cairo_line_to(cr, p.x(), top + plot_h);
      cairo_stroke(cr);
      set_colour(cr, {0, 0, 0});
      draw_text(cr, p.x() - 3.5 * static_cast<double>(label.size()), top + plot_h + 18, label, 12);
    }
    const double ys = tick_step(y_max - y_min, 6);
    for (double y = std::ceil(y_min / ys) * ys; y <= y_max + 1e-9 * ys; y += ys) {
      const Eigen::Vector2d p = to_px(x_min, y);
      set_colour(cr, {0.88, 0.88, 0.88});
      cairo_move_to(cr, left, p.y());
      cairo_line_to(cr, left + plot_w, p.y());
      cairo_stroke(cr);
      set_colour(cr, {0, 0, 0});
      draw_text(cr, 20, p.y() + 4, fmt::format("{:.3g}", std::abs(y) < 1e-12 ? 0.0 : y), 12);
    }
    set_colour(cr, {0, 0, 0});
    cairo_rectangle(cr, left, top, plot_w, plot_h);
    cairo_stroke(cr);

    for (const ChartSeries& s : chart.series) {
      // Band: one polygon per run of finite points.
      std::size_t i = 0;
      while (i < s.points.size()) {
        std::size_t j = i;
        while (j < s.points.size() && std::isfinite(s.points[j].y)) ++j;
        if (j - i >= 1) {
          bool has_band = false;
          for (std::size_t k = i; k < j; ++k)
            has_band |= s.points[k].y_lo != s.points[k].y || s.points[k].y_hi != s.points[k].y;
          if (has_band && j - i >= 2) {
            for (std::size_t k = i; k < j; ++k) {
              const Eigen::Vector2d p = to_px(s.points[k].x, s.points[k].y_hi);
              k == i ? cairo_move_to(cr, p.x(), p.y()) : cairo_line_to(cr, p.x(), p.y());
            }
            for (std::size_t k = j; k-- > i;) {
              const Eigen::Vector2d p = to_px(s.points[k].x, s.points[k].y_lo);
              cairo_line_to(cr, p.x(), p.y());
            }
            cairo_close_path(cr);
            set_colour(cr, s.colour, 0.15);
            cairo_fill(cr);
          } else if (has_band) {
            const Eigen::Vector2d lo = to_px(s.points[i].x, s.points[i].y_lo);
            const Eigen::Vector2d hi = to_px(s.points[i].x, s.points[i].y_hi);
            set_colour(cr, s.colour, 0.5);
            cairo_move_to(cr, lo.x(), lo.y());
            cairo_line_to(cr, hi.x(), hi.y());
            cairo_stroke(cr);
          }
        }
        i = j + 1;
      }
      // Line (broken at missing values) and markers.
      set_colour(cr, s.colour);
      cairo_set_line_width(cr, 2.0);
      const double dash[] = {7.0, 4.0};
      cairo_set_dash(cr, dash, s.dashed ? 2 : 0, 0);
      bool pen_down = false;
      for (const ChartPoint& point : s.points) {
        if (!std::isfinite(point.y)) {
          pen_down = false;
          continue;
        }
        const Eigen::Vector2d p = to_px(point.x, point.y);
        pen_down ? cairo_line_to(cr, p.x(), p.y()) : cairo_move_to(cr, p.x(), p.y());
        pen_down = true;
      }
      cairo_stroke(cr);
      cairo_set_dash(cr, nullptr, 0, 0);
      for (const ChartPoint& point : s.points) {
        if (std::isfinite(point.y)) {
          const Eigen::Vector2d p = to_px(point.x, point.y);
          cairo_arc(cr, p.x(), p.y(), 3.5, 0, 2 * M_PI);
          cairo_fill(cr);
        } else {  // no value: a cross on the top edge
          const Eigen::Vector2d p = to_px(point.x, y_max);
          cairo_set_line_width(cr, 2.0);
          cairo_move_to(cr, p.x() - 5, p.y() - 5);
          cairo_line_to(cr, p.x() + 5, p.y() + 5);
          cairo_move_to(cr, p.x() + 5, p.y() - 5);
          cairo_line_to(cr, p.x() - 5, p.y() + 5);
          cairo_stroke(cr);
        }
      }
    }

    // Titles, axis labels, legend.
    set_colour(cr, {0, 0, 0});
    draw_text(cr, left, 26, chart.title, 15, true);
    draw_text(cr, left, 46, chart.subtitle, 11);
    draw_text(cr, left + plot_w / 2 - 3.2 * static_cast<double>(chart.x_label.size()), kHeight - 18,
              chart.x_label, 13);
    cairo_save(cr);
    cairo_translate(cr, 14, top + plot_h / 2 + 3.2 * static_cast<double>(chart.y_label.size()));
    cairo_rotate(cr, -M_PI / 2);
    draw_text(cr, 0, 0, chart.y_label, 13);
    cairo_restore(cr);
    double y = top + 10;
    for (const ChartSeries& s : chart.series) {
      const double dash[] = {7.0, 4.0};
      cairo_set_dash(cr, dash, s.dashed ? 2 : 0, 0);
      y = legend_line(cr, left + plot_w + 16, y, s.colour, 2.0, s.label);
      cairo_set_dash(cr, nullptr, 0, 0);
    }
    if (any_missing) {
      set_colour(cr, {0, 0, 0});
      draw_text(cr, left + plot_w + 16, y + 8, "x on the top edge: no value", 11);
    }
  });
}

}  // namespace wifislam::plot
