#pragma once
// Each of the paper's numbers (paper_numbers.hpp) beside ours (paper_measurements.hpp), judged
// (verdict.hpp). What "ours" is for each kind of number is written here once:
//
//   table cells        the same twin, setting and variant of the same front end's runs;
//                      loop-closure time: study/result_columns.hpp's paper_loop_closure_s;
//                      Wi-Fi overhead: over vanilla's loop-closure time in the same setting;
//                      false negatives: % of revisit episodes without a correct closure (a twin
//                      with no revisit episode has no such %: not applicable);
//   frames             our dataset's frames scaled to the paper's 30 fps (route duration x 30);
//   access points      the twin's;
//   Wi-Fi clusters     the RTAB-Map Wi-Fi run at no time threshold (every twin has one);
//   RGBD-SLAM's text   C Hall at inlier_distance 3 (our default): Wi-Fi's wrong-place %, its
//                      saving of the bounded-module time and of the trajectory error;
//   RTAB-Map's nodes   vanilla's keyframes (RTAB-Map's nodes) at no time threshold;
//   "none" and "less than" over a whole part (RTAB-Map's false positives and its false
//                      negatives at 200 ms and no threshold, ORB-SLAM's Wi-Fi false positives
//                      and its false negatives below min-matches 100): per seed, the largest
//                      value of any run it covers, so one run against the claim is enough to
//                      miss it (false negatives: of runs whose route revisits a place);
//   ORB-SLAM's text    the saving and overhead as the paper's averages are made (below);
//                      keyframes: the mean of both variants (the paper does not say which);
//   FAB-MAP            ours (wifi-clusters): share of all queries within 4 m;
//   the abstract       "improve the accuracy of visual SLAM algorithms by 11% on average": the
//                      mean over RTAB-Map's 16 twin x threshold cells of Wi-Fi's relative
//                      reduction of the trajectory error (the paper's own table gives 11.2 % this
//                      way); "reduce computation time on average by 15% to 25%":
//                      ORB-SLAM's per-building means over min-matches of Wi-Fi's relative saving of
//                      loop-closure time (the paper's table gives 14.6, 24.1 and 20.5 % for C, B
//                      and J this way). Ours: the same means, per seed.

#include <string>
#include <vector>

#include "study/paper/paper_measurements.hpp"
#include "study/paper/paper_numbers.hpp"
#include "study/paper/verdict.hpp"

namespace wifislam::study::paper {

struct ComparedNumber {
  const PaperNumber* paper = nullptr;
  /// Ours for the same cell (per seed), as the verdict compared it, in the paper's unit; empty
  /// when not measured. For a pair's time the cell's seconds (the verdict used the ratio).
  Measured ours;
  Judgement judgement;
  /// Measured facts that explain a departure (revisit episodes, closures, clusters), or why a
  /// number has no counterpart.
  std::string context;
};

/// Every paper number, in paper_numbers() order.
std::vector<ComparedNumber> compare_with_paper(const PaperMeasurements& ours);

/// Settings as the runs name them: the paper's "min_matches=50" for RGBD-SLAM is our
/// "min_matches=50 inlier_distance=3".
std::string run_setting(const PaperNumber& number);

}  // namespace wifislam::study::paper
