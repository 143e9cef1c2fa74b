#pragma once
// What flows between the pipeline and a front end for one new keyframe: the query a front end
// selects candidates for, the candidates (each with the role that chose it), the hypotheses that
// passed visual verification, and the report of what became of them.

#include <string>
#include <vector>

#include "core/timestamp.hpp"
#include "slam/feature/frame_features.hpp"
#include "slam/frontend/loop_rule.hpp"
#include "slam/graph/pose_graph.hpp"
#include "slam/solve/visual_transformation.hpp"

namespace wifislam::slam::frontend {

/// Why a keyframe is compared with the new one. RGBD-SLAM's three groups (paper, "RGBD SLAM"):
/// predecessors and geodesic neighbours (motion estimation), long-term candidates (RGBDSLAMv2's
/// "sampled" keyframes, for long-term loop closure); the recent keyframes the pipeline tries when
/// tracking was lost; and RTAB-Map's proximity detection by space (nodes near the estimated
/// position, RGBD/ProximityBySpace). timing.json keeps per-role counters under these names, and
/// "tracking" for the frame-to-keyframe matches of tracking itself.
enum class CandidateRole { kPredecessor, kNeighbour, kLongTerm, kRelocalisation, kProximity };
std::string to_string(CandidateRole role);
inline constexpr const char* kTrackingRole = "tracking";

struct Candidate {
  graph::KeyframeId keyframe = -1;
  CandidateRole role = CandidateRole::kLongTerm;
  friend bool operator==(const Candidate&, const Candidate&) = default;
};

/// What a front end may look at for a new keyframe. The keyframe is already a graph node (its
/// pose is the tracking estimate) and recorded in the loop rule.
struct SelectionQuery {
  graph::KeyframeId keyframe = -1;
  Timestamp time;
  const feature::FrameFeatures* features = nullptr;
  const graph::PoseGraph* graph = nullptr;
  const LoopRule* loop_rule = nullptr;
  /// Keyframes already compared with this one (the tracking edge's source): do not return them.
  std::vector<graph::KeyframeId> already_compared;
};

/// A candidate whose visual transformation passed verification, classified by the front end.
struct Hypothesis {
  Candidate candidate;
  solve::VisualTransformation transformation;
  graph::EdgeType edge_type = graph::EdgeType::kVisual;  // kVisual or kLoop
};

/// The result of verifying one candidate.
struct ComparisonOutcome {
  Candidate candidate;
  bool verified = false;  // the transformation passed verification
  bool accepted = false;  // ... and the front end's acceptance made it an edge
  int inliers = 0;
  graph::EdgeType edge_type = graph::EdgeType::kVisual;  // meaningful when accepted
};

/// Everything the pipeline learned about a new keyframe, handed to the front end afterwards.
struct VerificationReport {
  graph::KeyframeId keyframe = -1;
  Timestamp time;
  /// The keyframe tracking matched it against (-1 when tracking was lost); that edge is visual.
  graph::KeyframeId tracked_from = -1;
  std::vector<ComparisonOutcome> comparisons;

  /// Keyframes this keyframe now has a visual or loop edge with (tracking edge included).
  std::vector<graph::KeyframeId> visually_connected() const;
};

}  // namespace wifislam::slam::frontend
