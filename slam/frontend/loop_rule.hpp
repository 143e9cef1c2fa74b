#pragma once
// When a match between two keyframes is a loop closure: the earlier one lies at least
// `min_keyframe_gap` keyframes back *and* at least `min_path_m` back along the estimated path
// (the tracking estimate when each keyframe was made). Keyframes are dense where the view changes
// fast, so an id gap alone would call a match 2 m further down a corridor a loop. The pipeline
// classifies edges with it, and a front end that looks for loop-closure candidates uses the same
// rule, so "loop closure" means one thing on both sides (and the evaluation's revisit distance is
// the default of min_path_m).

#include <vector>

#include "slam/graph/pose_graph.hpp"

namespace wifislam::slam::frontend {

class LoopRule {
 public:
  LoopRule(int min_keyframe_gap, double min_path_m)
      : min_keyframe_gap_(min_keyframe_gap), min_path_m_(min_path_m) {}

  /// Records the next keyframe's estimated path length from the start (ids 0, 1, ...).
  void add_keyframe(double path_m) { path_m_.push_back(path_m); }
  /// Estimated path length from the start to `keyframe` (0 for an unknown id).
  double path_m(graph::KeyframeId keyframe) const {
    return keyframe >= 0 && static_cast<std::size_t>(keyframe) < path_m_.size()
               ? path_m_[static_cast<std::size_t>(keyframe)]
               : 0.0;
  }
  std::size_t keyframes() const { return path_m_.size(); }

  /// Whether an edge between `earlier` and `later` (both recorded) would be a loop closure.
  bool is_loop(graph::KeyframeId earlier, graph::KeyframeId later) const {
    return later - earlier >= min_keyframe_gap_ && path_m(later) - path_m(earlier) >= min_path_m_;
  }

  int min_keyframe_gap() const { return min_keyframe_gap_; }
  double min_path_m() const { return min_path_m_; }

 private:
  int min_keyframe_gap_;
  double min_path_m_;
  std::vector<double> path_m_;
};

}  // namespace wifislam::slam::frontend
