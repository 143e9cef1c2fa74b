#pragma once
// Pose-graph optimisation with Ceres: positions in R^3, orientations on the quaternion manifold,
// one relative-pose residual per edge, the first keyframe held fixed (gauge).

#include <string>

#include "slam/graph/pose_graph.hpp"

namespace wifislam::slam {

struct PoseGraphOptions {
  /// Iterations of the final, full optimisation at the end of a run.
  int max_iterations = 100;
  /// Iterations of the incremental optimisation after a keyframe brought loop closures; starts
  /// from the current estimate, so few are needed. Fewer: faster, less converged in between.
  int incremental_max_iterations = 10;
  /// Robust loss on loop-closure edges: "none", "huber" or "cauchy". A robust loss limits the
  /// damage of a false loop closure, but the vanilla systems the paper compares use none.
  std::string robust_loss = "none";
  /// Scale of the robust loss, in units of the whitened residual (standard deviations).
  double robust_loss_scale = 3.0;
  /// Ceres threads for residual evaluation (the factorisation is single-threaded anyway).
  int threads = 1;
};

struct OptimisationSummary {
  bool ran = false;
  int iterations = 0;
  double initial_cost = 0.0, final_cost = 0.0;
  double seconds = 0.0;
  std::string brief;  // Ceres' BriefReport()
};

/// Optimises the poses of `graph` in place, with node `fixed_node` held constant.
OptimisationSummary optimise_pose_graph(PoseGraph& graph, const PoseGraphOptions& options,
                                        int max_iterations, KeyframeId fixed_node = 0);

}  // namespace wifislam::slam
