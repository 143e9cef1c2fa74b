#pragma once
// Which verified hypotheses become graph edges: the part of loop closing where the three families
// differ most after candidate selection (docs/frontends.md).
//   all               every verified hypothesis (RGBD-SLAM: the back end sorts them out later)
//   best              every ordinary visual hypothesis, and of the loop hypotheses only the one
//                     with most inliers (RTAB-Map and ORB-SLAM close at most one loop per node);
//                     RTAB-Map's proximity links (role proximity) are added beside it, as
//                     Rtabmap::process adds them, so they are kept like visual ones
//   graph-consistent  another policy's choice, tried in a copy of the graph: after optimisation
//                     no link's error may exceed a bound in its own standard deviations
//                     (RTAB-Map's RGBD/OptimizeMaxError, Graph.cpp computeMaxGraphErrors);
//                     otherwise the new loop edge with the largest error ratio is dropped and the
//                     rest tried again. A confident false loop closure is nearly satisfied after
//                     optimisation and shows as torn links elsewhere, so every link is checked,
//                     not only the new ones.
// A policy returns indices into the hypotheses, in the order their edges are to be added.

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "slam/frontend/candidate.hpp"
#include "slam/graph/pose_graph.hpp"
#include "slam/optimize/pose_graph_optimizer.hpp"

namespace wifislam::slam::frontend {

/// The graph as it stands before the new keyframe's verified edges are added.
struct AcceptanceContext {
  const graph::PoseGraph* graph = nullptr;
  graph::KeyframeId keyframe = -1;
  /// False when tracking was lost: the keyframe's pose then comes from its first accepted edge.
  bool keyframe_has_pose = true;
  /// Edges the pipeline may add besides the hypotheses (wheel odometry to the previous
  /// keyframe): part of the trial graph, so a loop closure must agree with them too. When
  /// tracking was lost a false relocalisation would otherwise hang on its own edge unopposed.
  std::vector<graph::GraphEdge> other_edges;
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

/// Error of an edge in a graph in its own standard deviations, as RTAB-Map's
/// computeMaxGraphErrors measures it: the largest per-axis translation error over the largest
/// translation standard deviation, and the rotation error (here the angle of the error rotation,
/// where RTAB-Map takes the largest Euler angle difference) over the largest rotation standard
/// deviation; the larger of the two. The standard deviations are marginal ones, from the
/// covariance (the inverse of the information): RTAB-Map's links are diagonal, where this is the
/// same as 1 / the information diagonal, but ours couple translation and rotation.
/// Returns nullopt for a link RTAB-Map skips: translation variance above 1 m^2 (our weak edges),
/// or an information matrix that is not positive definite.
std::optional<double> edge_error_ratio(const graph::PoseGraph& graph, const graph::GraphEdge& edge);

class AcceptGraphConsistentHypotheses final : public EdgeAcceptance {
 public:
  /// `max_error_ratio`: RTAB-Map's RGBD/OptimizeMaxError (3.0). `iterations`: optimiser
  /// iterations per trial.
  AcceptGraphConsistentHypotheses(std::unique_ptr<EdgeAcceptance> inner, double max_error_ratio,
                                  optimize::PoseGraphOptions graph_options, int iterations);
  std::string name() const override { return inner_->name() + "+graph_consistent"; }
  std::vector<std::size_t> choose(const std::vector<Hypothesis>& hypotheses,
                                  const AcceptanceContext& context) const override;

 private:
  std::unique_ptr<EdgeAcceptance> inner_;
  double max_error_ratio_;
  optimize::PoseGraphOptions graph_options_;
  int iterations_;
};

}  // namespace wifislam::slam::frontend
