#pragma once
// The pose graph: nodes are keyframes (camera-to-map poses), edges are relative-pose
// constraints with information matrices, of four kinds:
//   odometry - wheel odometry between keyframes (bridges tracking loss when available);
//   visual   - a visual transformation between keyframes close in the sequence;
//   loop     - a visual transformation to a keyframe far back in the sequence (loop closure);
//   weak     - a low-information "stayed about here" link that keeps a new segment attached when
//              tracking is lost and there is no odometry (the graph stays one connected piece).

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/pose.hpp"
#include "core/timestamp.hpp"

namespace wifislam::slam::graph {

using KeyframeId = int;
using Information6 = Eigen::Matrix<double, 6, 6>;

enum class EdgeType { kOdometry, kVisual, kLoop, kWeak };
std::string to_string(EdgeType type);

struct GraphNode {
  KeyframeId id = -1;
  Timestamp time;
  std::int64_t frame_index = 0;
  Pose pose = Pose::Identity();  // camera-to-map
};

struct GraphEdge {
  KeyframeId from = -1, to = -1;
  EdgeType type = EdgeType::kVisual;
  /// Pose of `to` in the frame of `from` (X_from = from_to * X_to).
  Pose from_to = Pose::Identity();
  /// Information of the residual [p_est - p_meas; 2 vec(q_meas q_est^-1)] (translation first).
  Information6 information = Information6::Identity();
  int inliers = 0;  // visual and loop edges; 0 otherwise
  /// Multiplies `information` in the optimisation: 1 as measured; below 1 when the after-run
  /// pruning discounted an edge it could not remove without disconnecting the graph.
  double weight = 1.0;
  /// Removed by the after-run pruning: kept in the graph (and in graph.json) for scoring, but no
  /// longer optimised.
  bool pruned = false;
};

class PoseGraph {
 public:
  /// Appends a node; ids are consecutive from 0.
  KeyframeId add_node(Timestamp time, std::int64_t frame_index, const Pose& pose);
  void add_edge(const GraphEdge& edge);

  std::size_t node_count() const { return nodes_.size(); }
  const std::vector<GraphNode>& nodes() const { return nodes_; }
  const std::vector<GraphEdge>& edges() const { return edges_; }
  const GraphNode& node(KeyframeId id) const { return nodes_.at(static_cast<std::size_t>(id)); }
  void set_pose(KeyframeId id, const Pose& pose) {
    nodes_.at(static_cast<std::size_t>(id)).pose = pose;
  }
  /// After-run pruning (slam/optimize/edge_pruning.hpp): the edge stays listed, out of the
  /// optimisation. Adjacency is unchanged: it describes the graph as it grew online.
  void prune_edge(std::size_t index) { edges_.at(index).pruned = true; }
  void set_edge_weight(std::size_t index, double weight) { edges_.at(index).weight = weight; }
  bool has_edge(KeyframeId a, KeyframeId b) const;
  /// Keyframes joined to `id` by an edge (pruned or not), ascending.
  const std::vector<KeyframeId>& adjacent(KeyframeId id) const {
    return adjacency_.at(static_cast<std::size_t>(id));
  }
  /// Keyframes within `depth` edges of `id` (excluding `id`), ordered by graph distance, then id.
  std::vector<KeyframeId> geodesic_neighbours(KeyframeId id, int depth) const;

 private:
  std::vector<GraphNode> nodes_;
  std::vector<GraphEdge> edges_;
  std::vector<std::vector<KeyframeId>> adjacency_;
};

}  // namespace wifislam::slam::graph
