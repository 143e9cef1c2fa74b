#include "plot/line_chart.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

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

namespace {

// Figure layout (px): the plot area, and margins for tick labels, titles and the legend.
constexpr int kWidth = 1000, kHeight = 560;
constexpr double kLeft = 80, kRight = 250, kTop = 70, kBottom = 64;
constexpr double kPlotW = kWidth - kLeft - kRight, kPlotH = kHeight - kTop - kBottom;
constexpr double kDash[] = {7.0, 4.0};

/// The data ranges the plot area shows, and the mapping from data to figure pixels.
struct ChartRange {
  double x_min = 0, x_max = 0, y_min = 0, y_max = 0;
  bool any_missing = false;  // some y is absent: drawn as a cross on the top edge

  Eigen::Vector2d to_px(double x, double y) const {
    return Eigen::Vector2d(kLeft + (x - x_min) / (x_max - x_min) * kPlotW,
                           kTop + kPlotH - (y - y_min) / (y_max - y_min) * kPlotH);
  }
};

/// Ranges over every finite value, bands included; categories span their slots; y padded.
ChartRange chart_range(const LineChart& chart) {
  ChartRange r;
  double x_min = std::numeric_limits<double>::infinity(), x_max = -x_min;
  double y_min = x_min, y_max = -x_min;
  for (const ChartSeries& s : chart.series) {
    for (const ChartPoint& p : s.points) {
      x_min = std::min(x_min, p.x);
      x_max = std::max(x_max, p.x);
      if (!std::isfinite(p.y)) {
        r.any_missing = true;
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
  r.x_min = x_min, r.x_max = x_max, r.y_min = y_min, r.y_max = y_max;
  return r;
}

void set_dash(cairo_t* cr, bool dashed) { cairo_set_dash(cr, kDash, dashed ? 2 : 0, 0); }

/// The x ticks and their labels: one per category, else nice steps over the range.
std::vector<std::pair<double, std::string>> x_ticks(const LineChart& chart, const ChartRange& r) {
  std::vector<std::pair<double, std::string>> ticks;
  if (!chart.x_categories.empty()) {
    for (std::size_t i = 0; i < chart.x_categories.size(); ++i)
      ticks.emplace_back(static_cast<double>(i), chart.x_categories[i]);
    return ticks;
  }
  const double xs = tick_step(r.x_max - r.x_min, 10);
  for (double x = std::ceil(r.x_min / xs) * xs; x <= r.x_max + 1e-9 * xs; x += xs)
    ticks.emplace_back(x, fmt::format("{:g}", std::abs(x) < 1e-12 ? 0.0 : x));
  return ticks;
}

/// Grid lines with tick labels on both axes, and the plot area's frame.
void draw_grid(cairo_t* cr, const LineChart& chart, const ChartRange& r) {
  for (const auto& [x, label] : x_ticks(chart, r)) {
    const Eigen::Vector2d p = r.to_px(x, r.y_min);
    set_colour(cr, {0.88, 0.88, 0.88});
    cairo_move_to(cr, p.x(), kTop);
    cairo_line_to(cr, p.x(), kTop + kPlotH);
    cairo_stroke(cr);
    set_colour(cr, {0, 0, 0});
    draw_text(cr, p.x() - 3.5 * static_cast<double>(label.size()), kTop + kPlotH + 18, label, 12);
  }
  const double ys = tick_step(r.y_max - r.y_min, 6);
  for (double y = std::ceil(r.y_min / ys) * ys; y <= r.y_max + 1e-9 * ys; y += ys) {
    const Eigen::Vector2d p = r.to_px(r.x_min, y);
    set_colour(cr, {0.88, 0.88, 0.88});
    cairo_move_to(cr, kLeft, p.y());
    cairo_line_to(cr, kLeft + kPlotW, p.y());
    cairo_stroke(cr);
    set_colour(cr, {0, 0, 0});
    draw_text(cr, 20, p.y() + 4, fmt::format("{:.3g}", std::abs(y) < 1e-12 ? 0.0 : y), 12);
  }
  set_colour(cr, {0, 0, 0});
  cairo_rectangle(cr, kLeft, kTop, kPlotW, kPlotH);
  cairo_stroke(cr);
}

/// The band of the run of finite points [i, j) of `s`: a translucent polygon, or for a run of
/// one point a vertical bar; nothing when no point of the run has a band.
void draw_band_run(cairo_t* cr, const ChartSeries& s, std::size_t i, std::size_t j,
                   const ChartRange& r) {
  bool has_band = false;
  for (std::size_t k = i; k < j; ++k)
    has_band |= s.points[k].y_lo != s.points[k].y || s.points[k].y_hi != s.points[k].y;
  if (has_band && j - i >= 2) {
    for (std::size_t k = i; k < j; ++k) {
      const Eigen::Vector2d p = r.to_px(s.points[k].x, s.points[k].y_hi);
      k == i ? cairo_move_to(cr, p.x(), p.y()) : cairo_line_to(cr, p.x(), p.y());
    }
    for (std::size_t k = j; k-- > i;) {
      const Eigen::Vector2d p = r.to_px(s.points[k].x, s.points[k].y_lo);
      cairo_line_to(cr, p.x(), p.y());
    }
    cairo_close_path(cr);
    set_colour(cr, s.colour, 0.15);
    cairo_fill(cr);
  } else if (has_band) {
    const Eigen::Vector2d lo = r.to_px(s.points[i].x, s.points[i].y_lo);
    const Eigen::Vector2d hi = r.to_px(s.points[i].x, s.points[i].y_hi);
    set_colour(cr, s.colour, 0.5);
    cairo_move_to(cr, lo.x(), lo.y());
    cairo_line_to(cr, hi.x(), hi.y());
    cairo_stroke(cr);
  }
}

/// Band: one polygon per run of finite points.
void draw_band(cairo_t* cr, const ChartSeries& s, const ChartRange& r) {
  std::size_t i = 0;
  while (i < s.points.size()) {
    std::size_t j = i;
    while (j < s.points.size() && std::isfinite(s.points[j].y)) ++j;
    if (j - i >= 1) draw_band_run(cr, s, i, j, r);
    i = j + 1;
  }
}

/// The line, broken at missing values.
void draw_line(cairo_t* cr, const ChartSeries& s, const ChartRange& r) {
  set_colour(cr, s.colour);
  cairo_set_line_width(cr, 2.0);
  set_dash(cr, s.dashed);
  bool pen_down = false;
  for (const ChartPoint& point : s.points) {
    if (!std::isfinite(point.y)) {
      pen_down = false;
      continue;
    }
    const Eigen::Vector2d p = r.to_px(point.x, point.y);
    pen_down ? cairo_line_to(cr, p.x(), p.y()) : cairo_move_to(cr, p.x(), p.y());
    pen_down = true;
  }
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
}

/// A dot at each value; a cross on the top edge where there is none.
void draw_markers(cairo_t* cr, const ChartSeries& s, const ChartRange& r) {
  for (const ChartPoint& point : s.points) {
    if (std::isfinite(point.y)) {
      const Eigen::Vector2d p = r.to_px(point.x, point.y);
      cairo_arc(cr, p.x(), p.y(), 3.5, 0, 2 * M_PI);
      cairo_fill(cr);
    } else {
      const Eigen::Vector2d p = r.to_px(point.x, r.y_max);
      cairo_set_line_width(cr, 2.0);
      cairo_move_to(cr, p.x() - 5, p.y() - 5);
      cairo_line_to(cr, p.x() + 5, p.y() + 5);
      cairo_move_to(cr, p.x() + 5, p.y() - 5);
      cairo_line_to(cr, p.x() - 5, p.y() + 5);
      cairo_stroke(cr);
    }
  }
}

/// Title, subtitle and the axis labels (the y label turned up the left edge).
void draw_titles(cairo_t* cr, const LineChart& chart) {
  set_colour(cr, {0, 0, 0});
  draw_text(cr, kLeft, 26, chart.title, 15, true);
  draw_text(cr, kLeft, 46, chart.subtitle, 11);
  draw_text(cr, kLeft + kPlotW / 2 - 3.2 * static_cast<double>(chart.x_label.size()), kHeight - 18,
            chart.x_label, 13);
  cairo_save(cr);
  cairo_translate(cr, 14, kTop + kPlotH / 2 + 3.2 * static_cast<double>(chart.y_label.size()));
  cairo_rotate(cr, -M_PI / 2);
  draw_text(cr, 0, 0, chart.y_label, 13);
  cairo_restore(cr);
}

/// One legend row per series right of the plot, and what a cross means when there is one.
void draw_legend(cairo_t* cr, const LineChart& chart, bool any_missing) {
  double y = kTop + 10;
  for (const ChartSeries& s : chart.series) {
    set_dash(cr, s.dashed);
    y = legend_line(cr, kLeft + kPlotW + 16, y, s.colour, 2.0, s.label);
    cairo_set_dash(cr, nullptr, 0, 0);
  }
  if (any_missing) {
    set_colour(cr, {0, 0, 0});
    draw_text(cr, kLeft + kPlotW + 16, y + 8, "x on the top edge: no value", 11);
  }
}

}  // namespace

void draw_line_chart(const std::filesystem::path& path, const LineChart& chart) {
  const ChartRange range = chart_range(chart);
  write_figure(path, kWidth, kHeight, [&](cairo_t* cr) {
    cairo_set_line_width(cr, 1.0);
    draw_grid(cr, chart, range);
    for (const ChartSeries& s : chart.series) {
      draw_band(cr, s, range);
      draw_line(cr, s, range);
      draw_markers(cr, s, range);
    }
    draw_titles(cr, chart);
    draw_legend(cr, chart, range.any_missing);
  });
}

}  // namespace wifislam::plot
