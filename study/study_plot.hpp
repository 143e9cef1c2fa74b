#pragma once
// `wifislam study plot`: a study database's curves, one figure per metric (PNG and SVG), and the
// numbers behind them in curves.csv.
//
// What goes where, from the study's axes:
//  - x: the first of access_points.count, appearance.aliasing that the study sweeps; otherwise
//    its first numeric axis with more than one value; otherwise its first axis with more than one
//    value (categorical).
//  - seeds (an axis named `seed` or ending in `.seed`) are pooled: each point is the median over
//    them, with a band from the smallest to the largest value;
//  - every other axis with more than one value splits the lines (e.g. one line per placement, so
//    co-linear and scattered APs are side by side), and so does the variant (SLAM level: Wi-Fi
//    solid, vanilla dashed, one colour per line of the other axes).
// An absent resolution (NULL: places never look different, or not even the nearest are
// recognised) counts as infinitely coarse in the median; a point whose median is that has no value
// and is drawn as a cross on the top edge.

#include <filesystem>
#include <string>
#include <vector>

#include "study/result_store.hpp"

namespace wifislam::study {

struct StudyPlotSummary {
  std::vector<std::filesystem::path> figures;  // PNG and SVG of each metric
  std::string x_axis;                          // the axis drawn along x
  std::vector<std::string> line_axes;          // the axes that split the lines
  std::vector<std::string> pooled_axes;        // the axes pooled into each point
};

/// Draws every metric of the table's level into `folder` (which must exist) and writes
/// `folder`/curves.csv: metric, line, x, cases, median, min, max.
StudyPlotSummary plot_study(const ResultTable& table, const std::filesystem::path& folder);

}  // namespace wifislam::study
