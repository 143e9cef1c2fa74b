#pragma once
// Which verified hypotheses become graph edges: the part of loop closing where the three families
// differ most after candidate selection (DESIGN.md, "The SLAM pipeline").
//   all               every verified hypothesis (RGBD-SLAM: the back end sorts them out later)
//   best              every ordinary visual hypothesis, and of the loop hypotheses only the one
//                     with most inliers (RTAB-Map and ORB-SLAM close at most one loop per node)
//   graph-consistent  another policy's choice, then each loop edge is tried in the graph: after
//                     optimisation its error against its own standard deviation must stay at or
//                     below a bound (RTAB-Map's RGBD/OptimizeMaxError), else the worst offender is
//                     dropped and the rest tried again
// A policy returns indices into the hypotheses, in the order their edges are to be added.

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "slam/frontend/candidate.hpp"
#include "slam/graph/pose_graph.hpp"
#include "slam/optimize/pose_graph_optimizer.hpp"

namespace wifislam::slam {

/// The graph as it stands before the new keyframe's verified edges are added.
struct AcceptanceContext {
  const PoseGraph* graph = nullptr;
  KeyframeId keyframe = -1;
  /// False when tracking was lost: the keyframe's pose then comes from its first accepted edge.
  bool keyframe_has_pose = true;
};

class EdgeAcceptance {
 public:
  virtual ~EdgeAcceptance() = default;
  virtual std::string name() const = 0;
  virtual std::vector<std::size_t> choose(const std::vector<Hypothesis>& hypotheses,
                                          const AcceptanceContext& context) const = 0;
};

class AcceptAllHypotheses final : public EdgeAcceptance {
 public:
  std::string name() const override { return "all"; }
  std::vector<std::size_t> choose(const std::vector<Hypothesis>& hypotheses,
                                  const AcceptanceContext& context) const override;
};

class AcceptBestLoopHypothesis final : public EdgeAcceptance {
 public:
  std::string name() const override { return "best"; }
  /// Ties in inliers go to the earlier hypothesis (the front end's verification order).
  std::vector<std::size_t> choose(const std::vector<Hypothesis>& hypotheses,
                                  const AcceptanceContext& context) const override;
};

/// Normalised error of an edge in a graph: the larger of |translation error| / sigma_t and
/// |rotation error| / sigma_r, with the sigmas the square roots of the largest translation and
/// rotation variances of the edge's covariance (inverse information), as RTAB-Map computes it.
double edge_error_ratio(const PoseGraph& graph, const GraphEdge& edge);

class AcceptGraphConsistentHypotheses final : public EdgeAcceptance {
 public:
  /// `max_error_ratio`: RTAB-Map's RGBD/OptimizeMaxError (3.0). `iterations`: optimiser
  /// iterations per trial.
  AcceptGraphConsistentHypotheses(std::unique_ptr<EdgeAcceptance> inner, double max_error_ratio,
                                  PoseGraphOptions graph_options, int iterations);
  std::string name() const override { return inner_->name() + "+graph_consistent"; }
  std::vector<std::size_t> choose(const std::vector<Hypothesis>& hypotheses,
                                  const AcceptanceContext& context) const override;

 private:
  std::unique_ptr<EdgeAcceptance> inner_;
  double max_error_ratio_;
  PoseGraphOptions graph_options_;
  int iterations_;
};

}  // namespace wifislam::slam
