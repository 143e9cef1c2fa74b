#pragma once
// A line chart of x-y series (cairo, PNG or SVG by extension): the study curves (metric against
// an axis, one line per variant or placement) and the greedy-placement curve. Each point may
// carry a band (e.g. min-max over seeds), drawn as a translucent area around the line. A point
// whose y is absent (NaN) breaks the line and is listed under the chart, so a value that does
// not exist (a resolution never reached) is not drawn as if it were a number.

#include <filesystem>
#include <string>
#include <vector>

#include "plot/canvas.hpp"

namespace wifislam::plot {

struct ChartPoint {
  double x = 0, y = 0;
  double y_lo = 0, y_hi = 0;  // the band; equal to y when there is none
};

struct ChartSeries {
  std::string label;
  Colour colour;
  bool dashed = false;
  std::vector<ChartPoint> points;  // in increasing x
};

struct LineChart {
  std::string title, subtitle, x_label, y_label;
  /// Names of the x values when x is categorical (x = 0, 1, 2, ...); empty for numeric x.
  std::vector<std::string> x_categories;
  std::vector<ChartSeries> series;
  /// y starts at 0 (counts, shares, metres) unless some value is negative.
  bool y_from_zero = true;
};

/// A "nice" tick step (1, 2 or 5 x 10^k) giving about `target` ticks over `range`.
double tick_step(double range, int target);

/// Draws `chart` into `path` (1000 x 560 px). Throws IoError when it cannot be written.
void draw_line_chart(const std::filesystem::path& path, const LineChart& chart);

}  // namespace wifislam::plot
