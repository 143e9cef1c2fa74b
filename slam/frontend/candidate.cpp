#include "slam/frontend/candidate.hpp"

#include <algorithm>

namespace wifislam::slam::frontend {

std::string to_string(CandidateRole role) {
  switch (role) {
    case CandidateRole::kPredecessor:
      return "predecessor";
    case CandidateRole::kNeighbour:
      return "neighbour";
    case CandidateRole::kLongTerm:
      return "long_term";
    case CandidateRole::kRelocalisation:
      return "relocalisation";
    case CandidateRole::kProximity:
      return "proximity";
  }
  return "unknown";
}

std::vector<graph::KeyframeId> VerificationReport::visually_connected() const {
  std::vector<graph::KeyframeId> out;
  if (tracked_from >= 0) out.push_back(tracked_from);
  for (const ComparisonOutcome& c : comparisons) {
    if (c.accepted) out.push_back(c.candidate.keyframe);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace wifislam::slam::frontend
