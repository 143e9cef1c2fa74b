#pragma once
// After-run pruning of inconsistent edges, as RGBDSLAMv2 does at the end of a run
// (OpenNIListener::evaluation, GraphManager::pruneEdgesWithErrorAbove): for each threshold of a
// decreasing schedule, every camera-to-camera edge (visual or loop) whose chi^2 at the current
// optimum exceeds it is removed, and the graph re-optimised when anything changed.
//
// An edge whose removal would split the graph is discounted instead (its weight drops to
// `discount_weight`): the nodes beyond it keep a pose. RGBDSLAMv2 tests only whether either end
// has no other edge; we test connectivity itself, which also protects an edge that is the only
// link between two long segments. Odometry and weak edges are never pruned (RGBDSLAMv2 keeps its
// odometry edges out of the pruned set too). RGBDSLAMv2 also replaces the measurement of a
// pruned consecutive edge by "no motion"; we keep every measurement as it was verified, since a
// discounted bridge carries no tension anyway.

#include <cstddef>
#include <functional>
#include <vector>

#include "slam/graph/pose_graph.hpp"
#include "slam/optimize/pose_graph_optimizer.hpp"

namespace wifislam::slam::optimize {

struct PruningSchedule {
  /// chi^2 thresholds (6 degrees of freedom, the edge's own information x weight), applied in
  /// this order; each must be positive. Empty: no pruning.
  std::vector<double> chi2_thresholds;
  /// Weight given to an edge that is over a threshold but cannot be removed.
  double discount_weight = 1e-6;
};

struct PruningStage {
  double threshold_chi2 = 0.0;
  int pruned = 0;      // edges removed at this stage
  int discounted = 0;  // edges that would have disconnected the graph, discounted instead
  OptimisationSummary optimisation;  // the re-optimisation after the stage (ran = false: none)
};

/// chi^2 = r^T (weight x Omega) r of `edge` at the graph's current poses.
double edge_chi2(const graph::PoseGraph& graph, const graph::GraphEdge& edge);

/// Runs the schedule on `graph` (already optimised). `reoptimise` is called after every stage
/// that changed something and returns its summary.
std::vector<PruningStage> prune_inconsistent_edges(
    graph::PoseGraph& graph, const PruningSchedule& schedule,
    const std::function<OptimisationSummary(graph::PoseGraph&)>& reoptimise);

}  // namespace wifislam::slam::optimize
