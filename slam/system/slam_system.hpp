#pragma once
// The visual SLAM pipeline: features -> tracking against the last keyframe -> keyframes ->
// candidate selection (the front end) -> visual verification -> acceptance (the front end) ->
// pose graph (Ceres). What differs between SLAM families is the front end's
// (slam/frontend/front_end.hpp); everything here is shared.
//
// Tracking: each frame is matched against the last keyframe. It becomes a keyframe when its
// inliers drop below `keyframe_min_inliers` or it moved beyond the keyframe bounds, or, for a
// front end with a keyframe schedule (RTAB-Map's nodes), when the schedule says so. When the
// match fails, the last well-tracked frame is promoted to keyframe and the match retried; if that
// fails too, the frame starts a keyframe without tracking edge, which candidate verification
// (plus the most recent keyframes) tries to relocalise; failing that, wheel odometry or a weak
// edge attaches it. Every frame gets a pose; nothing here throws on bad data.

#include <memory>
#include <optional>
#include <vector>

#include "core/camera_intrinsics.hpp"
#include "core/sensor_stream.hpp"
#include "core/tum_trajectory.hpp"
#include "slam/feature/feature_store.hpp"
#include "slam/feature/orb_feature_extractor.hpp"
#include "slam/frontend/front_end.hpp"
#include "slam/frontend/loop_rule.hpp"
#include "slam/graph/pose_graph.hpp"
#include "slam/optimize/pose_graph_optimizer.hpp"
#include "slam/slam_options.hpp"
#include "slam/util/instrumentation.hpp"

namespace wifislam::slam::system {

/// Where a frame is: relative to a keyframe, so it follows that keyframe through optimisation.
struct FramePoseRecord {
  Timestamp time;
  std::int64_t frame_index = 0;
  graph::KeyframeId keyframe = -1;
  Pose keyframe_from_frame = Pose::Identity();
};

struct LoopClosureRecord {
  graph::KeyframeId from = -1, to = -1;  // from = the earlier keyframe
  frontend::CandidateRole role = frontend::CandidateRole::kLongTerm;
  int inliers = 0;
  double rms_reprojection_px = 0.0;
  Pose from_to = Pose::Identity();
};

/// Sensor facts the pipeline needs besides frames (from the SensorStream).
struct StreamInfo {
  CameraIntrinsics intrinsics;
  Pose camera_in_base = Pose::Identity();
  bool has_wifi = false;
  bool has_odometry = false;
};

class SlamSystem {
 public:
  /// Validates the options and builds the front end named by `options.frontend` (with a Wi-Fi
  /// module when `options.wifi.enabled`).
  SlamSystem(const SlamOptions& options, const StreamInfo& stream);
  ~SlamSystem();
  SlamSystem(const SlamSystem&) = delete;
  SlamSystem& operator=(const SlamSystem&) = delete;

  /// Feeds one event of the stream (frames, Wi-Fi scans, odometry in time order).
  void process(const SensorEvent& event);
  void process_frame(const RgbdFrame& frame);
  /// Full optimisation of the graph, then the front end's after-run pruning; call once at the end.
  void finish();
  /// Takes every frame's features from `store` (slam/feature/feature_store.hpp) instead of
  /// extracting them: its frames need no images then. The store must hold every frame this
  /// system is fed, made with this system's FeatureOptions (std::invalid_argument otherwise;
  /// std::logic_error at a frame it lacks); it must outlive the system.
  void use_feature_store(const feature::FeatureStore* store);

  const SlamOptions& options() const { return options_; }
  const graph::PoseGraph& graph() const { return graph_; }
  const std::vector<FramePoseRecord>& frame_records() const { return frames_; }
  const std::vector<LoopClosureRecord>& loop_closures() const { return loop_closures_; }
  const util::Instrumentation& instrumentation() const { return instrumentation_; }
  util::Instrumentation& instrumentation() { return instrumentation_; }
  const frontend::FrontEnd& front_end() const { return *front_end_; }
  const frontend::LoopRule& loop_rule() const { return loop_rule_; }
  const optimize::OptimisationSummary& final_optimisation() const { return final_optimisation_; }
  /// The after-run pruning stages finish() ran (the front end's schedule; empty: none).
  const std::vector<optimize::PruningStage>& pruning() const { return pruning_; }
  const StreamInfo& stream_info() const { return stream_; }

  /// Camera-to-map pose of every frame processed so far (current graph estimate).
  Trajectory trajectory() const;
  /// Camera-to-map pose of every keyframe.
  Trajectory keyframe_trajectory() const;

 private:
  struct TrackedFrame {
    feature::FrameFeatures features;
    Pose keyframe_from_frame;
    int inliers = 0;
    graph::Information6 information;
    std::optional<Pose> odometry_camera;
  };
  struct TrackingEdge {
    graph::KeyframeId from;
    Pose from_to;
    graph::Information6 information;
    int inliers;
  };

  /// Whether a frame tracked by `t` from the last keyframe becomes the next keyframe: the front
  /// end's schedule when it has one, else the tracking-quality rule.
  bool needs_new_keyframe(const solve::VisualTransformation& t, Timestamp frame_time) const;
  std::optional<Pose> current_odometry_camera() const;
  /// What verifying a keyframe's candidates found: the report for the front end, and the
  /// comparisons that passed as hypotheses (with the index of each one's outcome in the report).
  struct Verification {
    frontend::VerificationReport report;
    std::vector<frontend::Hypothesis> hypotheses;
    std::vector<std::size_t> outcome_of_hypothesis;
  };

  /// Adds a keyframe, verifies its candidates, attaches it, optimises after loop closures.
  void add_keyframe(feature::FrameFeatures features, std::optional<Pose> odometry_camera,
                    const std::optional<TrackingEdge>& tracking);
  /// The keyframe's graph node, records, loop-rule path length and tracking edge; returns its id.
  /// `previous` is the last keyframe before it (-1: none).
  graph::KeyframeId insert_keyframe(feature::FrameFeatures features,
                                    const std::optional<Pose>& odometry_camera,
                                    graph::KeyframeId previous,
                                    const std::optional<TrackingEdge>& tracking);
  /// Candidate selection, verification and acceptance for new keyframe `id`, then its
  /// attachment; timed as loop-closure detection. Returns whether a loop closed.
  bool search_loop_closures(graph::KeyframeId id, graph::KeyframeId previous,
                            const std::optional<Pose>& odometry_camera,
                            const std::optional<TrackingEdge>& tracking);
  /// The front end's candidates, plus (when tracking was lost) the most recent searchable
  /// keyframes for relocalisation.
  std::vector<frontend::Candidate> select_candidates(graph::KeyframeId id,
                                                     graph::KeyframeId previous,
                                                     const std::optional<TrackingEdge>& tracking);
  /// Compares the new keyframe with every candidate; the front end classifies what passes.
  /// Throws std::logic_error when the front end named a keyframe that is not an earlier one.
  Verification verify_candidates(const std::vector<frontend::Candidate>& candidates,
                                 graph::KeyframeId id, const std::optional<TrackingEdge>& tracking);
  /// Wheel odometry from the previous keyframe, when the stream has it for both.
  std::optional<graph::GraphEdge> odometry_edge_to(
      graph::KeyframeId id, graph::KeyframeId previous,
      const std::optional<Pose>& odometry_camera) const;
  /// The front end's acceptance policy picks the hypotheses that become edges (indices into
  /// `hypotheses`). It sees the odometry edge the keyframe may get (always with odometry_edges,
  /// else when tracking was lost), so a graph-consistency check weighs a loop closure against it.
  std::vector<std::size_t> choose_hypotheses(const std::vector<frontend::Hypothesis>& hypotheses,
                                             graph::KeyframeId id, bool tracked,
                                             const std::optional<graph::GraphEdge>& odometry_edge);
  /// Adds the accepted hypotheses as edges and marks them in the report; an untracked keyframe
  /// takes its pose from the first. Returns whether one is a loop closure.
  bool add_accepted_edges(const std::vector<std::size_t>& accepted, graph::KeyframeId id,
                          bool tracked, Verification& verification);
  /// Attaches a keyframe nothing visual connects by odometry, else by a weak edge (and adds the
  /// odometry edge anyway when odometry_edges asks for it).
  void attach_if_unconnected(graph::KeyframeId id, graph::KeyframeId previous,
                             const std::optional<graph::GraphEdge>& odometry_edge);
  /// Incremental optimisation after a loop closure or on the front end's schedule.
  void optimise_if_due(graph::KeyframeId id, bool loop_found);
  /// Visual transformation between two frames; its work is booked under `role`.
  solve::VisualTransformation compare(const feature::FrameFeatures& a,
                                      const feature::FrameFeatures& b, const std::string& role);
  /// One optimisation with the front end's kernel; counts it, and a failure.
  optimize::OptimisationSummary optimise(int max_iterations, double convergence = 0.0);

  SlamOptions options_;
  StreamInfo stream_;
  util::Instrumentation instrumentation_;
  std::unique_ptr<feature::OrbFeatureExtractor> extractor_;
  const feature::FeatureStore* feature_store_ = nullptr;
  std::unique_ptr<frontend::FrontEnd> front_end_;
  graph::PoseGraph graph_;
  std::vector<feature::FrameFeatures> keyframe_features_;
  std::vector<std::optional<Pose>> keyframe_odometry_;  // camera pose in the odometry frame
  frontend::LoopRule loop_rule_;  // knows every keyframe's estimated path length
  std::vector<FramePoseRecord> frames_;
  std::vector<LoopClosureRecord> loop_closures_;
  std::optional<TrackedFrame> last_tracked_;
  std::optional<OdometryReading> last_odometry_;
  frontend::GraphRobustness robustness_;  // the front end's, fixed for the run
  std::optional<frontend::KeyframeSchedule>
      keyframe_schedule_;  // the front end's, fixed for the run
  optimize::OptimisationSummary final_optimisation_;
  std::vector<optimize::PruningStage> pruning_;
};

}  // namespace wifislam::slam::system
