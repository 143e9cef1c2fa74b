#pragma once
// ORB-SLAM2's temporal consistency of loop candidates (LoopClosing::DetectLoop, Mur-Artal & Tardós
// 2017): a candidate is accepted only when it and its covisible keyframes (its group) have kept
// overlapping the groups of earlier queries' candidates for `threshold` (3) consecutive
// keyframes. Each query's candidate groups are compared with the groups kept from the previous
// query: a group that shares a keyframe with a kept group inherits its count plus one (each kept
// group extended at most once), one that shares none starts at 0; the groups of this query
// replace the kept ones, and a query without candidates clears them.

#include <set>
#include <utility>
#include <vector>

#include "slam/graph/pose_graph.hpp"

namespace wifislam::slam::bow {

class LoopConsistency {
 public:
  explicit LoopConsistency(int threshold = 3) : threshold_(threshold) {}

  /// One query's candidates, each with its group (the candidate and its covisible keyframes).
  /// Returns the candidates consistent enough to be verified, in the order given.
  std::vector<graph::KeyframeId> update(
      const std::vector<std::pair<graph::KeyframeId, std::set<graph::KeyframeId>>>& candidates);

  /// Forgets every kept group (ORB-SLAM2 does after a loop is closed or a query is skipped).
  void clear() { kept_.clear(); }
  std::size_t kept_groups() const { return kept_.size(); }

 private:
  int threshold_;
  std::vector<std::pair<std::set<graph::KeyframeId>, int>> kept_;  // group, consistency count
};

}  // namespace wifislam::slam::bow
