#pragma once
// RGBD-SLAM's options (its front end: rgbdslam_front_end.hpp), in their own header as rtabmap's
// and orbslam's are, so that slam_options.hpp, which holds every front end's options, includes
// no front end.

#include <string>
#include <vector>

#include "slam/optimize/robust_kernel.hpp"

namespace wifislam::slam::frontend::rgbdslam {

/// Defaults are RGBDSLAMv2's current ones (parameter_server.cpp, since 2015): 4 / 4 / 4. Its
/// defaults before 2015 were 2 / 2 / 2 (`--set predecessor_candidates=2 --set
/// neighbor_candidates=2 --set min_sampled_candidates=2`).
struct RgbdslamOptions {
  /// The most recent keyframes compared with every new keyframe (`predecessor_candidates`).
  int predecessor_candidates = 4;
  /// Keyframes sampled among the geodesic neighbours of the previous keyframe
  /// (`neighbor_candidates`) within `geodesic_depth` edges (3). After a loop closure these
  /// reach back to the revisited place, which keeps the loop "closed" from then on.
  int neighbor_candidates = 4;
  int geodesic_depth = 3;
  /// Random earlier keyframes per new keyframe (`min_sampled_candidates`): the only source of
  /// long-term loop closures; the chance of drawing the right one falls as the map grows.
  int min_sampled_candidates = 4;
  /// With a Wi-Fi module: long-term candidates taken from the ranked pool of similar clusters.
  /// -1 = `min_sampled_candidates` (Wi-Fi never verifies more than vanilla); 0 = the whole pool
  /// (exhaustive: the costliest reading of "compare the current frame only to keyframes within
  /// similar clusters").
  int wifi_long_term_candidates = -1;

  /// The robust back end (RGBDSLAMv2 GraphManager: a Huber kernel on every edge; at the end of a
  /// run, edges over chi^2 5, then 1, then 0.25 pruned with a re-optimisation after each).
  ///
  /// RGBDSLAMv2's information is not calibrated (inliers / rmse^2 x identity, rmse a unitless 3-D
  /// Mahalanobis distance), so its numbers cannot be carried over: on our information, whose
  /// chi^2 follows chi^2(6) for correct edges (docs: README, "Robust back end"), a threshold of
  /// 0.25 would prune every edge. We keep its schedule's shape, 20 : 4 : 1 with the kernel at 4x
  /// the last stage, and anchor the last stage at the 99.9 % quantile of chi^2(6) (22.46): an
  /// edge measured as well as it claims is pruned with probability 0.1 %.
  optimize::RobustKernel::Kind robust_kernel = optimize::RobustKernel::Kind::kHuber;
  double robust_kernel_chi2 = 4 * 22.46;  // where the kernel leaves the quadratic
  /// After-run pruning stages, chi^2 thresholds in order; empty: no pruning ("none").
  std::vector<double> prune_chi2 = {449.2, 89.84, 22.46};

  /// Incremental optimisation after every n-th keyframe, besides after each keyframe that brought
  /// a loop closure (RGBDSLAMv2's `optimizer_skip_step`, default 1). 0: after loop closures only.
  int optimizer_skip_step = 1;
  /// How far each incremental optimisation goes (RGBDSLAMv2's `optimizer_iterations`, default
  /// 0.01, which below 1 means: GraphManager::optimizeGraphImpl runs rounds of 5 iterations
  /// until a round lowers the graph's chi^2 by less than this fraction, at least two rounds and
  /// no cap). A graph torn between conflicting edges takes more rounds than a consistent one.
  /// Ours caps the rounds at `optimizer_iterations` (the final optimisation's, 100) as a guard.
  /// 0: at most `optimizer_incremental_iterations`, the pipeline's fixed budget.
  double optimizer_convergence = 0.01;
};

}  // namespace wifislam::slam::frontend::rgbdslam
