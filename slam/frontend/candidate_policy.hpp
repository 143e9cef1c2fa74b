#pragma once
// The one concern every front end has: for a new keyframe, which earlier keyframes to verify, in
// what order and why (memory and candidate policy; paper, "General approach"). The shared
// pipeline verifies them; what becomes an edge is the front end's EdgeAcceptance.

#include <vector>

#include "slam/frontend/candidate.hpp"

namespace wifislam::slam::frontend {

class CandidatePolicy {
 public:
  virtual ~CandidatePolicy() = default;

  /// Memory: whether `keyframe` may be compared with a new keyframe at all (relocalisation
  /// candidates are filtered by it). Default: every keyframe.
  virtual bool searchable(graph::KeyframeId /*keyframe*/) const { return true; }

 protected:
  /// Candidates for the new keyframe of `query`, in the order they should be verified.
  virtual std::vector<Candidate> select(const SelectionQuery& query) = 0;
};

}  // namespace wifislam::slam::frontend
