#include "slam/system/slam_system.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include <fmt/format.h>

#include "core/wall_clock.hpp"
#include "slam/frontend/front_end_registry.hpp"

namespace wifislam::slam::system {

namespace {

graph::Information6 diagonal_information(double sigma_m, double sigma_rad) {
  graph::Information6 info = graph::Information6::Zero();
  info.diagonal().head<3>().setConstant(1.0 / (sigma_m * sigma_m));
  info.diagonal().tail<3>().setConstant(1.0 / (sigma_rad * sigma_rad));
  return info;
}

}  // namespace

SlamSystem::SlamSystem(const SlamOptions& options, const StreamInfo& stream)
    : options_(options),
      stream_(stream),
      loop_rule_(options.tracking.loop_min_keyframe_gap, options.tracking.loop_min_path_m) {
  validate(options_);
  extractor_ =
      std::make_unique<feature::OrbFeatureExtractor>(options_.features, stream_.intrinsics);
  frontend::FrontEndContext context;
  context.options = &options_;
  context.instrumentation = &instrumentation_;
  context.stream_has_wifi = stream_.has_wifi;
  context.stream_has_odometry = stream_.has_odometry;
  front_end_ = frontend::make_front_end(context);
  robustness_ = front_end_->schedule().robustness;
  keyframe_schedule_ = front_end_->schedule().keyframes;
}

SlamSystem::~SlamSystem() = default;

void SlamSystem::process(const SensorEvent& event) {
  util::ScopedTimer total(instrumentation_, module::kTotal);
  if (const auto* frame = std::get_if<RgbdFrame>(&event)) {
    process_frame(*frame);
  } else if (const auto* scan = std::get_if<WifiScan>(&event)) {
    front_end_->observe_wifi_scan(*scan);
  } else if (const auto* odometry = std::get_if<OdometryReading>(&event)) {
    last_odometry_ = *odometry;
    front_end_->observe_odometry(*odometry);
  }
}

std::optional<Pose> SlamSystem::current_odometry_camera() const {
  if (!last_odometry_) return std::nullopt;
  return last_odometry_->base_in_odom * stream_.camera_in_base;
}

solve::VisualTransformation SlamSystem::compare(const feature::FrameFeatures& a,
                                                const feature::FrameFeatures& b,
                                                const std::string& role) {
  const std::int64_t ransac_before = instrumentation_.counter(counter::kRansacRuns);
  const auto start = std::chrono::steady_clock::now();
  solve::VisualTransformation t = solve::estimate_visual_transformation(
      a, b, stream_.intrinsics, options_.transform, instrumentation_);
  instrumentation_.record_comparison(role,
                                     instrumentation_.counter(counter::kRansacRuns) - ransac_before,
                                     t.accepted, seconds_since(start));
  return t;
}

bool SlamSystem::needs_new_keyframe(const solve::VisualTransformation& t,
                                    Timestamp frame_time) const {
  if (keyframe_schedule_) {
    const graph::KeyframeId last = static_cast<graph::KeyframeId>(graph_.node_count()) - 1;
    return keyframe_schedule_->due(frame_time.ns - graph_.node(last).time.ns, t.a_from_b);
  }
  const int min_inliers =
      std::max(options_.tracking.keyframe_min_inliers, options_.transform.min_matches);
  return t.inliers < min_inliers ||
         t.a_from_b.translation().norm() > options_.tracking.keyframe_max_translation_m ||
         Eigen::AngleAxisd(t.a_from_b.linear()).angle() >
             options_.tracking.keyframe_max_rotation_rad;
}

void SlamSystem::use_feature_store(const feature::FeatureStore* store) {
  if (store != nullptr && !(store->options() == options_.features)) {
    throw std::invalid_argument("feature store made with other feature options than the run's");
  }
  feature_store_ = store;
}

void SlamSystem::process_frame(const RgbdFrame& frame) {
  instrumentation_.count(counter::kFrames);
  feature::FrameFeatures features;
  if (feature_store_ != nullptr) {
    const feature::FeatureStore::Entry* entry = feature_store_->find(frame.index);
    if (entry == nullptr) {
      throw std::logic_error(fmt::format("feature store has no frame {}", frame.index));
    }
    features = *entry->features;
    // Charged as if extracted here (feature_store.hpp): total too, which process() times.
    instrumentation_.add_time(module::kFeatureExtraction, entry->extraction_s);
    instrumentation_.add_seconds(module::kTotal, entry->extraction_s);
  } else {
    util::ScopedTimer timer(instrumentation_, module::kFeatureExtraction);
    features = extractor_->extract(frame);
  }
  const std::optional<Pose> odometry = current_odometry_camera();
  if (graph_.node_count() == 0) {
    add_keyframe(std::move(features), odometry, std::nullopt);
    return;
  }

  // Against the last keyframe: accepted and within bounds -> tracked; accepted but beyond the
  // bounds -> new keyframe; rejected -> promote the last tracked frame and retry once.
  for (int attempt = 0; attempt < 2; ++attempt) {
    const auto keyframe = static_cast<graph::KeyframeId>(graph_.node_count() - 1);
    const solve::VisualTransformation t = compare(
        keyframe_features_[static_cast<std::size_t>(keyframe)], features, frontend::kTrackingRole);
    if (t.accepted) instrumentation_.record_role_accepted(frontend::kTrackingRole);
    if (t.accepted && !needs_new_keyframe(t, frame.time)) {
      frames_.push_back({frame.time, frame.index, keyframe, t.a_from_b});
      last_tracked_ =
          TrackedFrame{std::move(features), t.a_from_b, t.inliers, t.information, odometry};
      return;
    }
    if (t.accepted) {
      add_keyframe(std::move(features), odometry,
                   TrackingEdge{keyframe, t.a_from_b, t.information, t.inliers});
      return;
    }
    if (attempt == 0) instrumentation_.count(counter::kTrackingFailures);
    if (!last_tracked_) break;
    TrackedFrame promoted = std::move(*last_tracked_);
    last_tracked_.reset();
    // Its record is re-made by add_keyframe (relative to itself).
    if (!frames_.empty() && frames_.back().frame_index == promoted.features.frame_index) {
      frames_.pop_back();
    }
    instrumentation_.count(counter::kKeyframesAfterTrackingLoss);
    add_keyframe(std::move(promoted.features), promoted.odometry_camera,
                 TrackingEdge{keyframe, promoted.keyframe_from_frame, promoted.information,
                              promoted.inliers});
  }
  instrumentation_.count(counter::kKeyframesAfterTrackingLoss);
  add_keyframe(std::move(features), odometry, std::nullopt);
}

void SlamSystem::add_keyframe(feature::FrameFeatures features, std::optional<Pose> odometry_camera,
                              const std::optional<TrackingEdge>& tracking) {
  instrumentation_.count(counter::kKeyframes);
  const graph::KeyframeId previous = static_cast<graph::KeyframeId>(graph_.node_count()) - 1;
  const graph::KeyframeId id =
      insert_keyframe(std::move(features), odometry_camera, previous, tracking);
  const bool loop_found = search_loop_closures(id, previous, odometry_camera, tracking);
  optimise_if_due(id, loop_found);
}

graph::KeyframeId SlamSystem::insert_keyframe(feature::FrameFeatures features,
                                              const std::optional<Pose>& odometry_camera,
                                              graph::KeyframeId previous,
                                              const std::optional<TrackingEdge>& tracking) {
  // Placed by the tracking edge when there is one, else where the previous keyframe is.
  Pose initial = previous >= 0 ? graph_.node(previous).pose : Pose::Identity();
  if (tracking) initial = graph_.node(tracking->from).pose * tracking->from_to;
  const graph::KeyframeId id = graph_.add_node(features.time, features.frame_index, initial);
  frames_.push_back({features.time, features.frame_index, id, Pose::Identity()});
  keyframe_features_.push_back(std::move(features));
  keyframe_odometry_.push_back(odometry_camera);
  loop_rule_.add_keyframe(
      previous < 0 ? 0.0
                   : loop_rule_.path_m(previous) +
                         (initial.translation() - graph_.node(previous).pose.translation()).norm());
  last_tracked_.reset();
  if (tracking) {
    graph_.add_edge({tracking->from, id, graph::EdgeType::kVisual, tracking->from_to,
                     tracking->information, tracking->inliers});
  }
  return id;
}

bool SlamSystem::search_loop_closures(graph::KeyframeId id, graph::KeyframeId previous,
                                      const std::optional<Pose>& odometry_camera,
                                      const std::optional<TrackingEdge>& tracking) {
  util::ScopedTimer detection(instrumentation_, module::kLoopClosureDetection);
  const std::vector<frontend::Candidate> candidates = select_candidates(id, previous, tracking);
  Verification verification = verify_candidates(candidates, id, tracking);
  const std::optional<graph::GraphEdge> odometry_edge =
      odometry_edge_to(id, previous, odometry_camera);
  const std::vector<std::size_t> accepted =
      choose_hypotheses(verification.hypotheses, id, tracking.has_value(), odometry_edge);
  const bool loop_found = add_accepted_edges(accepted, id, tracking.has_value(), verification);
  attach_if_unconnected(id, previous, odometry_edge);
  front_end_->on_verified(verification.report);
  instrumentation_.record_keyframe_search(id, static_cast<std::int64_t>(candidates.size()),
                                          detection.stop());
  return loop_found;
}

std::vector<frontend::Candidate> SlamSystem::select_candidates(
    graph::KeyframeId id, graph::KeyframeId previous, const std::optional<TrackingEdge>& tracking) {
  frontend::SelectionQuery query;
  query.keyframe = id;
  query.time = keyframe_features_.back().time;
  query.features = &keyframe_features_.back();
  query.graph = &graph_;
  query.loop_rule = &loop_rule_;
  if (tracking) query.already_compared.push_back(tracking->from);
  std::vector<frontend::Candidate> candidates;
  {
    util::ScopedTimer selection(instrumentation_, module::kCandidateSelection);
    candidates = front_end_->candidates_for(query);
  }
  if (!tracking) {
    // Lost: also try the most recent searchable keyframes (relocalisation).
    for (graph::KeyframeId k = previous;
         k >= 0 && k > previous - options_.tracking.relocalisation_keyframes; --k) {
      const bool listed =
          std::any_of(candidates.begin(), candidates.end(),
                      [&](const frontend::Candidate& c) { return c.keyframe == k; });
      if (!listed && front_end_->searchable(k)) {
        candidates.push_back({k, frontend::CandidateRole::kRelocalisation});
      }
    }
  }
  return candidates;
}

SlamSystem::Verification SlamSystem::verify_candidates(
    const std::vector<frontend::Candidate>& candidates, graph::KeyframeId id,
    const std::optional<TrackingEdge>& tracking) {
  const feature::FrameFeatures& current = keyframe_features_.back();
  Verification v;
  v.report.keyframe = id;
  v.report.time = current.time;
  v.report.tracked_from = tracking ? tracking->from : -1;
  for (const frontend::Candidate& candidate : candidates) {
    if (candidate.keyframe < 0 || candidate.keyframe >= id) {
      throw std::logic_error(fmt::format("front end {} named keyframe {} as a candidate of {}",
                                         front_end_->name(), candidate.keyframe, id));
    }
    instrumentation_.count(counter::kCandidateComparisons);
    const solve::VisualTransformation t =
        compare(keyframe_features_[static_cast<std::size_t>(candidate.keyframe)], current,
                to_string(candidate.role));
    frontend::ComparisonOutcome outcome{candidate, t.accepted, false, t.inliers,
                                        graph::EdgeType::kVisual};
    if (t.accepted) {
      outcome.edge_type = loop_rule_.is_loop(candidate.keyframe, id) ? graph::EdgeType::kLoop
                                                                     : graph::EdgeType::kVisual;
      v.outcome_of_hypothesis.push_back(v.report.comparisons.size());
      v.hypotheses.push_back({candidate, t, outcome.edge_type});
    }
    v.report.comparisons.push_back(outcome);
  }
  return v;
}

std::optional<graph::GraphEdge> SlamSystem::odometry_edge_to(
    graph::KeyframeId id, graph::KeyframeId previous,
    const std::optional<Pose>& odometry_camera) const {
  if (!(previous >= 0 && odometry_camera &&
        keyframe_odometry_[static_cast<std::size_t>(previous)])) {
    return std::nullopt;
  }
  const Pose from_to =
      keyframe_odometry_[static_cast<std::size_t>(previous)]->inverse() * *odometry_camera;
  return graph::GraphEdge{previous,
                          id,
                          graph::EdgeType::kOdometry,
                          from_to,
                          diagonal_information(options_.tracking.odometry_sigma_m,
                                               options_.tracking.odometry_sigma_rad),
                          0};
}

std::vector<std::size_t> SlamSystem::choose_hypotheses(
    const std::vector<frontend::Hypothesis>& hypotheses, graph::KeyframeId id, bool tracked,
    const std::optional<graph::GraphEdge>& odometry_edge) {
  std::vector<std::size_t> accepted;
  {
    util::ScopedTimer acceptance(instrumentation_, module::kEdgeAcceptance);
    frontend::AcceptanceContext context{&graph_, id, tracked, {}};
    if (odometry_edge && (options_.tracking.odometry_edges || !tracked)) {
      context.other_edges.push_back(*odometry_edge);
    }
    accepted = front_end_->acceptance().choose(hypotheses, context);
  }
  for (std::size_t k = 0; k < accepted.size(); ++k) {
    if (accepted[k] >= hypotheses.size() || (k > 0 && accepted[k] <= accepted[k - 1])) {
      throw std::logic_error("acceptance policy " + front_end_->acceptance().name() +
                             " returned indices that are not ascending, unique and in range");
    }
  }
  instrumentation_.count(counter::kRejectedHypotheses,
                         static_cast<std::int64_t>(hypotheses.size() - accepted.size()));
  return accepted;
}

bool SlamSystem::add_accepted_edges(const std::vector<std::size_t>& accepted, graph::KeyframeId id,
                                    bool tracked, Verification& verification) {
  bool loop_found = false;
  bool have_pose = tracked;
  for (std::size_t i : accepted) {
    const frontend::Hypothesis& h = verification.hypotheses.at(i);
    const solve::VisualTransformation& t = h.transformation;
    graph_.add_edge({h.candidate.keyframe, id, h.edge_type, t.a_from_b, t.information, t.inliers});
    verification.report.comparisons[verification.outcome_of_hypothesis[i]].accepted = true;
    instrumentation_.record_role_accepted(to_string(h.candidate.role));
    if (!have_pose) {
      graph_.set_pose(id, graph_.node(h.candidate.keyframe).pose * t.a_from_b);
      have_pose = true;
    }
    if (h.edge_type == graph::EdgeType::kLoop) {
      loop_closures_.push_back({h.candidate.keyframe, id, h.candidate.role, t.inliers,
                                t.rms_reprojection_px, t.a_from_b});
      instrumentation_.count(counter::kLoopClosures);
      loop_found = true;
    }
  }
  return loop_found;
}

void SlamSystem::attach_if_unconnected(graph::KeyframeId id, graph::KeyframeId previous,
                                       const std::optional<graph::GraphEdge>& odometry_edge) {
  if (previous < 0) return;
  const bool unattached = graph_.adjacent(id).empty();
  if (odometry_edge && (unattached || options_.tracking.odometry_edges)) {
    graph_.add_edge(*odometry_edge);
    if (unattached) graph_.set_pose(id, graph_.node(previous).pose * odometry_edge->from_to);
  } else if (unattached) {
    graph_.add_edge(
        {previous, id, graph::EdgeType::kWeak, Pose::Identity(),
         diagonal_information(options_.tracking.weak_sigma_m, options_.tracking.weak_sigma_rad),
         0});
  }
}

void SlamSystem::optimise_if_due(graph::KeyframeId id, bool loop_found) {
  const int every = front_end_->schedule().optimise_every_keyframes;
  // Every n-th keyframe after the first (a graph of one node has nothing to optimise).
  const bool scheduled = every > 0 && id > 0 && id % every == 0;
  if ((loop_found || scheduled) && options_.graph.incremental_max_iterations > 0) {
    util::ScopedTimer timer(instrumentation_, module::kOptimisation);
    const double convergence = front_end_->schedule().optimisation_convergence;
    // Rounds until converged are capped by the final optimisation's budget instead.
    optimise(convergence > 0.0 ? options_.graph.max_iterations
                               : options_.graph.incremental_max_iterations,
             convergence);
  }
}

optimize::OptimisationSummary SlamSystem::optimise(int max_iterations, double convergence) {
  optimize::OptimisationSummary summary = optimize::optimise_pose_graph(
      graph_, options_.graph, max_iterations, robustness_.kernel, 0, convergence);
  if (summary.ran) {
    instrumentation_.count(counter::kOptimisations);
    instrumentation_.count(counter::kOptimisationIterations, summary.iterations);
  }
  if (!summary.usable) instrumentation_.count(counter::kOptimisationFailures);
  return summary;
}

void SlamSystem::finish() {
  util::ScopedTimer timer(instrumentation_, module::kOptimisation);
  final_optimisation_ = optimise(options_.graph.max_iterations);
  pruning_ = optimize::prune_inconsistent_edges(
      graph_, robustness_.pruning,
      [&](graph::PoseGraph&) { return optimise(options_.graph.max_iterations); });
  for (const optimize::PruningStage& stage : pruning_) {
    instrumentation_.count(counter::kPrunedEdges, stage.pruned);
    instrumentation_.count(counter::kDiscountedEdges, stage.discounted);
  }
}

Trajectory SlamSystem::trajectory() const {
  Trajectory out;
  out.reserve(frames_.size());
  for (const FramePoseRecord& r : frames_) {
    out.push_back(
        StampedPose::from_pose(r.time, graph_.node(r.keyframe).pose * r.keyframe_from_frame));
  }
  return out;
}

Trajectory SlamSystem::keyframe_trajectory() const {
  Trajectory out;
  out.reserve(graph_.node_count());
  for (const graph::GraphNode& node : graph_.nodes()) {
    out.push_back(StampedPose::from_pose(node.time, node.pose));
  }
  return out;
}

}  // namespace wifislam::slam::system
