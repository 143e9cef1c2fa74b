#pragma once
// The seam where front ends differ (DESIGN.md, "The SLAM pipeline"): which earlier keyframes a
// new keyframe is compared with. The pipeline asks a CandidateSelector for candidates, verifies
// each with a visual transformation, and tells the selector what came of it. A Wi-Fi-aware
// selector uses the same calls: it sees every Wi-Fi scan in stream order (clustering), bounds
// the candidates (bounding), and learns after verification which keyframes got visual edges
// (cluster management).

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/sensor_stream.hpp"
#include "core/wifi_scan.hpp"
#include "slam/feature/frame_features.hpp"
#include "slam/graph/pose_graph.hpp"

namespace wifislam::slam {

/// Why a keyframe is a candidate (the paper's three groups for RGBD SLAM, plus the recent
/// keyframes tried when tracking was lost).
enum class CandidateRole { kPredecessor, kNeighbour, kSampled, kRelocalisation };
std::string to_string(CandidateRole role);

struct Candidate {
  KeyframeId keyframe = -1;
  CandidateRole role = CandidateRole::kSampled;
  friend bool operator==(const Candidate&, const Candidate&) = default;
};

/// What a selector may look at for a new keyframe. The keyframe is already a graph node; its
/// pose is the tracking estimate.
struct SelectionQuery {
  KeyframeId keyframe = -1;
  Timestamp time;
  const FrameFeatures* features = nullptr;
  const PoseGraph* graph = nullptr;
  /// Keyframes already compared with this one (the tracking edge's source): do not return them.
  std::vector<KeyframeId> already_compared;
};

/// The result of verifying one candidate.
struct ComparisonOutcome {
  Candidate candidate;
  bool accepted = false;
  int inliers = 0;
  EdgeType edge_type = EdgeType::kVisual;  // meaningful when accepted
};

/// Everything the pipeline learned about a new keyframe, handed to the selector afterwards.
struct VerificationReport {
  KeyframeId keyframe = -1;
  Timestamp time;
  /// The keyframe tracking matched it against (-1 when tracking was lost); that edge is visual.
  KeyframeId tracked_from = -1;
  std::vector<ComparisonOutcome> comparisons;

  /// Keyframes this keyframe now has a visual or loop edge with (tracking edge included).
  std::vector<KeyframeId> visually_connected() const;
};

class CandidateSelector {
 public:
  virtual ~CandidateSelector() = default;
  /// The front end's name as given on the command line ("rgbdslam").
  virtual std::string name() const = 0;

  /// Sensor events other than frames, in stream order, before any later frame is processed.
  virtual void observe_wifi_scan(const WifiScan& /*scan*/) {}
  virtual void observe_odometry(const OdometryReading& /*reading*/) {}

  /// Candidates for a new keyframe, in the order they should be verified.
  virtual std::vector<Candidate> select(const SelectionQuery& query) = 0;

  /// Called once per new keyframe after all its candidates were verified.
  virtual void on_verified(const VerificationReport& /*report*/) {}

  /// Extra files for the run folder (e.g. wifi_clusters.csv) and a JSON summary for run.json.
  virtual void write_outputs(const std::filesystem::path& /*run_dir*/) const {}
  virtual nlohmann::json summary() const { return nlohmann::json::object(); }
};

}  // namespace wifislam::slam
