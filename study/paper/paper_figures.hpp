#pragma once
// The paper's figures redrawn from our runs (PNG and SVG in the folder's figures/), and charts of
// its tables with ours beside each number:
//   RGBD-SLAM   the 3 x 4 sweep (false positives, time, error against min-matches, one line per
//               inlier distance), the 50/70 comparison, the bad maps (min-matches 100 and 150 at
//               inlier distance 2) and the 50/70 maps;
//   RTAB-Map    each table per building (ours with its seeds' range, the paper's dashed), and
//               the J Hall and A Hall maps at 70 ms;
//   ORB-SLAM    each table per building, as RTAB-Map's;
//   FAB-MAP     each twin's error CDF (its first seed).

#include <filesystem>
#include <string>
#include <vector>

#include "study/paper/paper_comparison.hpp"
#include "study/paper/paper_measurements.hpp"

namespace wifislam::study::paper {

struct PaperFigure {
  Part part = Part::kRgbdslam;
  std::string file;  // relative to the folder ("figures/rgbdslam_sweep_time.png")
  std::string caption;
};

/// Draws (or copies) every figure the folder's runs allow into <folder>/figures/; a figure whose
/// runs are missing is left out.
std::vector<PaperFigure> draw_paper_figures(const PaperMeasurements& measurements,
                                            const std::vector<ComparedNumber>& compared,
                                            const std::filesystem::path& folder);

}  // namespace wifislam::study::paper
