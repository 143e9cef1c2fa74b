#pragma once
// Pose-graph optimisation with Ceres: positions in R^3, orientations on the quaternion manifold,
// one relative-pose residual per edge (information x the edge's weight; pruned edges left out),
// an optional robust kernel, the first keyframe held fixed (gauge). Poses are written back only
// when Ceres reports a usable solution.

#include <string>

#include "slam/graph/pose_graph.hpp"
#include "slam/optimize/robust_kernel.hpp"

namespace wifislam::slam::optimize {

struct PoseGraphOptions {
  /// Iterations of the final, full optimisation at the end of a run.
  int max_iterations = 100;
  /// Iterations of the incremental optimisation after a keyframe brought loop closures; starts
  /// from the current estimate, so few are needed. Fewer: faster, less converged in between.
  int incremental_max_iterations = 10;
  /// Ceres threads for residual evaluation (the factorisation is single-threaded anyway).
  int threads = 1;
};

struct OptimisationSummary {
  bool ran = false;
  /// Ceres' verdict (Solver::Summary::IsSolutionUsable). When false the graph's poses were left
  /// as they were before the call.
  bool usable = true;
  std::string termination;  // Ceres' termination type and message
  int iterations = 0;
  double initial_cost = 0.0, final_cost = 0.0;
  double seconds = 0.0;
  std::string brief;  // Ceres' BriefReport()
};

/// Optimises the poses of `graph` in place, with node `fixed_node` held constant. The robust
/// kernel is the front end's choice (FrontEndSchedule::robustness).
///
/// `convergence` 0: one solve of at most `max_iterations` Levenberg-Marquardt iterations (Ceres'
/// own tolerances may stop it sooner). `convergence` > 0: RGBDSLAMv2's schedule
/// (GraphManager::optimizeGraphImpl with `optimizer_iterations` below 1): rounds of
/// kConvergenceRoundIterations iterations, each a fresh solve from the last estimate as g2o's
/// optimize(5) is, until a round lowers the graph's chi^2 (without the kernel, as g2o's chi2()) by
/// less than that fraction; at least two rounds, and `max_iterations` in all at most.
OptimisationSummary optimise_pose_graph(graph::PoseGraph& graph, const PoseGraphOptions& options,
                                        int max_iterations, const RobustKernel& kernel = {},
                                        graph::KeyframeId fixed_node = 0, double convergence = 0.0);

inline constexpr int kConvergenceRoundIterations = 5;

}  // namespace wifislam::slam::optimize
