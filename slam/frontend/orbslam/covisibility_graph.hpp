#pragma once
// ORB-SLAM's covisibility graph (Mur-Artal et al. 2015, "Covisibility graph") without map points:
// two keyframes are covisible when a verified visual transformation between them has at least
// `min_weight` inliers (ORB-SLAM: 15 shared map points), and the edge's weight is that inlier
// count (the largest when a pair was verified more than once). Inliers of a verified RANSAC
// transformation are the closest we have to "map points seen by both".

#include <map>
#include <vector>

#include "slam/graph/pose_graph.hpp"

namespace wifislam::slam::frontend::orbslam {

class CovisibilityGraph {
 public:
  explicit CovisibilityGraph(int min_weight = 15) : min_weight_(min_weight) {}

  /// Records a verified pair; ignored below the minimum weight.
  void add(graph::KeyframeId a, graph::KeyframeId b, int inliers);

  int weight(graph::KeyframeId a, graph::KeyframeId b) const;
  /// Every covisible keyframe of `k` (ORB-SLAM2 GetConnectedKeyFrames), ascending.
  std::vector<graph::KeyframeId> connected(graph::KeyframeId k) const;
  /// The `n` covisible keyframes of `k` with the largest weights, largest first (ties: the
  /// newer keyframe first); n < 0: all of them (GetBestCovisibilityKeyFrames).
  std::vector<graph::KeyframeId> best(graph::KeyframeId k, int n) const;
  std::size_t edge_count() const { return edges_; }
  int min_weight() const { return min_weight_; }

 private:
  int min_weight_;
  std::map<graph::KeyframeId, std::map<graph::KeyframeId, int>> weights_;
  std::size_t edges_ = 0;
};

}  // namespace wifislam::slam::frontend::orbslam
