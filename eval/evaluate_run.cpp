#include "eval/evaluate_run.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <map>
#include <set>
#include <utility>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/dataset_calibration.hpp"
#include "core/dataset_format.hpp"
#include "core/dataset_reader.hpp"
#include "core/dataset_recording.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/run_format.hpp"
#include "core/tum_trajectory.hpp"
#include "eval/association.hpp"
#include "eval/dataset_depth.hpp"
#include "eval/graph_edges_json.hpp"
#include "eval/loop_closure_csv.hpp"
#include "eval/trajectory_error.hpp"

namespace wifislam::eval {

namespace fs = std::filesystem;

namespace {

fs::path required_file(const fs::path& folder, const char* name, const char* what) {
  const fs::path p = folder / name;
  require_input_file(p, what);
  return p;
}

std::vector<Timestamp> times_of(const Trajectory& t) {
  std::vector<Timestamp> out;
  out.reserve(t.size());
  for (const StampedPose& p : t) out.push_back(p.time);
  return out;
}

std::vector<Pose> poses_of(const Trajectory& t) {
  std::vector<Pose> poses;
  poses.reserve(t.size());
  for (const StampedPose& p : t) poses.push_back(p.pose());
  return poses;
}

/// What run.json says about the run: the front end and whether the Wi-Fi module ran. A folder
/// without run.json (a run written by another tool) is a run without Wi-Fi of an unnamed front
/// end. Format version 1 (before "wifi" existed) named a Wi-Fi run "<frontend>+wifi".
struct RunIdentity {
  std::string frontend;
  bool wifi = false;
  /// frontend_summary.node_time_s.cost, for a front end with a deterministic cost model.
  std::optional<double> cost_model_s;
  /// frontend_summary.loop_closure_time_s: its cost-model share and the measured CPU time of
  /// likelihood and posterior (rtabmap).
  std::optional<double> loop_closure_cost_s, likelihood_posterior_cpu_s;
  /// frontend_summary.loop_closure_time_s.query: the loop query's measured time (orbslam).
  std::optional<double> loop_query_s;
  /// input.recording: the recording the run was made from (core/dataset_recording.hpp); absent
  /// for runs written before it was kept and by other tools.
  std::optional<DatasetRecording> recording;
};

/// The number of seconds at `keys` under run.json's object `j`, when present; a clear error when
/// it is not a number >= 0.
std::optional<double> optional_seconds(const nlohmann::json& j,
                                       std::initializer_list<const char*> keys,
                                       const fs::path& run_json) {
  const nlohmann::json* at = &j;
  std::string path;
  for (const char* k : keys) {
    at = at->is_object() && at->contains(k) ? &(*at)[k] : nullptr;
    if (at == nullptr) return std::nullopt;
    path += (path.empty() ? "" : ".") + std::string(k);
  }
  if (!at->is_number() || !(at->get<double>() >= 0.0)) {
    throw ParseError(run_json.string(), path, "expected a number of seconds >= 0");
  }
  return at->get<double>();
}

RunIdentity identity_of(const fs::path& run_json) {
  namespace key = run_folder::run_key;
  RunIdentity id;
  if (!input_file_present(run_json, "the run's identity")) return id;
  std::ifstream in(run_json);
  nlohmann::json j;
  try {
    in >> j;
  } catch (const nlohmann::json::exception& e) {
    throw ParseError(run_json.string(), "", std::string("not valid JSON: ") + e.what());
  }
  if (!j.is_object()) throw ParseError(run_json.string(), "", "expected a JSON object");
  if (j.contains(key::kFormatVersion)) {
    const nlohmann::json& v = j[key::kFormatVersion];
    if (!v.is_number_integer() || v.get<int>() < 1 || v.get<int>() > run_folder::kFormatVersion) {
      throw ParseError(run_json.string(), key::kFormatVersion,
                       fmt::format("expected a run format version from 1 to {} (this build's), "
                                   "got {}",
                                   run_folder::kFormatVersion, v.dump()));
    }
  }
  if (j.contains(key::kFrontend)) {
    if (!j[key::kFrontend].is_string()) {
      throw ParseError(run_json.string(), key::kFrontend, "expected a string");
    }
    id.frontend = j[key::kFrontend].get<std::string>();
  }
  if (j.contains(key::kWifi)) {
    if (!j[key::kWifi].is_boolean()) {
      throw ParseError(run_json.string(), key::kWifi, "expected true or false");
    }
    id.wifi = j[key::kWifi].get<bool>();
  } else if (id.frontend.ends_with("+wifi")) {
    id.frontend.resize(id.frontend.size() - 5);
    id.wifi = true;
  }
  id.cost_model_s = optional_seconds(j, {"frontend_summary", "node_time_s", "cost"}, run_json);
  id.loop_closure_cost_s =
      optional_seconds(j, {"frontend_summary", "loop_closure_time_s", "cost"}, run_json);
  id.likelihood_posterior_cpu_s = optional_seconds(
      j, {"frontend_summary", "loop_closure_time_s", "likelihood_posterior_cpu"}, run_json);
  id.loop_query_s =
      optional_seconds(j, {"frontend_summary", "loop_closure_time_s", "query"}, run_json);
  if (j.contains("input") && j["input"].is_object() && j["input"].contains("recording")) {
    id.recording =
        recording_from_json(j["input"]["recording"], run_json.string(), "input.recording");
  }
  return id;
}

/// Scored edges from graph.json (every accepted edge, pruned or not) or, for a run without one,
/// from loop_closures.csv, each keyframe pair once (`repeated_csv_rows` counts the rows that name
/// an earlier row's pair, in either order); the csv's candidate role is joined onto graph edges by
/// (from, to).
std::vector<AcceptedEdge> accepted_edges(const fs::path& graph_file,
                                         const std::vector<DetectedLoopClosure>& csv_rows,
                                         const fs::path& csv_file,
                                         std::int64_t& repeated_csv_rows) {
  std::map<std::pair<std::int64_t, std::int64_t>, std::string> role_of;
  for (const DetectedLoopClosure& lc : csv_rows)
    role_of[{lc.from_keyframe, lc.to_keyframe}] = lc.role;
  std::vector<AcceptedEdge> edges;
  if (fs::is_regular_file(graph_file)) {
    for (const GraphEdgeRecord& g : read_graph_edges_json(graph_file)) {
      AcceptedEdge e;
      e.from_keyframe = g.from_keyframe;
      e.to_keyframe = g.to_keyframe;
      e.type = g.type;
      const auto role = role_of.find({g.from_keyframe, g.to_keyframe});
      if (role != role_of.end()) e.role = role->second;
      e.inliers = g.inliers;
      e.from_to = g.from_to;
      e.pruned = g.pruned;
      e.weight = g.weight;
      e.where = graph_file.string();
      e.from_key = fmt::format("{}[{}].{}", run_folder::graph_key::kEdges, g.index,
                               run_folder::graph_key::kFrom);
      e.to_key = fmt::format("{}[{}].{}", run_folder::graph_key::kEdges, g.index,
                             run_folder::graph_key::kTo);
      edges.push_back(std::move(e));
    }
    return edges;
  }
  std::set<std::pair<std::int64_t, std::int64_t>> pairs_seen;
  for (const DetectedLoopClosure& lc : csv_rows) {
    if (!pairs_seen.insert(std::minmax(lc.from_keyframe, lc.to_keyframe)).second) {
      ++repeated_csv_rows;
      continue;
    }
    AcceptedEdge e;
    e.from_keyframe = lc.from_keyframe;
    e.to_keyframe = lc.to_keyframe;
    e.type = run_folder::edge_type::kLoop;
    e.role = lc.role;
    e.inliers = lc.inliers;
    e.from_to = lc.from_to;
    e.where = fmt::format("{}:{}", csv_file.string(), lc.line);
    e.from_key = "from_keyframe";
    e.to_key = "to_keyframe";
    edges.push_back(std::move(e));
  }
  return edges;
}

/// Everything a run's evaluation reads, read and checked before anything is computed.
struct RunInputs {
  bool bare_trajectory = false;
  fs::path run_dir;  // empty for a bare trajectory
  Trajectory ground_truth, estimated, keyframes;
  fs::path trajectory_file, keyframes_file, clusters_file;
  std::vector<AcceptedEdge> edges;
  DatasetCalibration calibration;
  std::int64_t offset_ns = 0;  // added to the estimate's stamps (time_offset_s, exact)
};

/// Reads the inputs; only the trajectory is required: a folder or file from another system has
/// nothing else. Records in `ev` what the inputs hold and what is not available, and why.
RunInputs read_inputs(const fs::path& input, const fs::path& dataset_dir,
                      const EvalOptions& options, bool verify_checksums, RunEvaluation& ev) {
  RunInputs in;
  // A path that is there but of the wrong kind is bad input (exit 2); one that is not, I/O.
  std::error_code ec;
  const fs::file_status input_status = fs::status(input, ec);
  // A pipe (`<(...)` in a shell) is read as a trajectory file, as every text input is.
  in.bare_trajectory = fs::is_regular_file(input_status) || fs::is_fifo(input_status);
  if (!fs::exists(input_status)) throw IoError(input.string() + ": not found");
  if (!in.bare_trajectory && !fs::is_directory(input_status)) {
    throw ParseError(input.string(), "",
                     "is neither a run folder nor a trajectory file (a device or socket)");
  }
  const fs::file_status dataset_status = fs::status(dataset_dir, ec);
  if (!fs::exists(dataset_status)) {
    throw IoError(dataset_dir.string() + ": dataset folder not found");
  }
  if (!fs::is_directory(dataset_status)) {
    throw ParseError(dataset_dir.string(), "",
                     "is not a folder; give the dataset folder (it holds groundtruth.txt)");
  }
  if (const std::optional<std::string> why = not_a_dataset(dataset_dir))
    throw InvalidInputError(*why);
  in.run_dir = in.bare_trajectory ? fs::path() : input;
  const auto optional_file = [&](const char* name) {
    return in.bare_trajectory || !input_file_present(in.run_dir / name, "a run folder's file")
               ? fs::path()
               : in.run_dir / name;
  };
  // Exactly the decimal given: an offset between Unix clocks has 16 digits or more, beyond what a
  // product with 1e9 in doubles keeps.
  in.offset_ns = Timestamp::from_seconds_exact(options.time_offset_s).ns;
  required_file(dataset_dir, dataset::kGroundTruth, "the dataset's ground truth");
  in.ground_truth = read_ground_truth(dataset_dir, verify_checksums);
  in.trajectory_file = in.bare_trajectory ? input
                                          : required_file(in.run_dir, run_folder::kTrajectory,
                                                          "the run's estimated trajectory");
  in.estimated = read_tum_trajectory(in.trajectory_file.string());
  in.keyframes_file = optional_file(run_folder::kKeyframes);
  const fs::path graph_file = optional_file(run_folder::kGraph);
  const fs::path loops_file = optional_file(run_folder::kLoopClosures);
  const fs::path timing_file = optional_file(run_folder::kTiming);
  if (!in.keyframes_file.empty()) in.keyframes = read_tum_trajectory(in.keyframes_file.string());
  const std::vector<DetectedLoopClosure> loops =
      loops_file.empty() ? std::vector<DetectedLoopClosure>{} : read_loop_closures_csv(loops_file);
  in.edges = accepted_edges(graph_file, loops, loops_file, ev.loop_closure_csv_repeated_rows);
  ev.loop_closure_csv_rows = static_cast<std::int64_t>(loops.size());
  if (!timing_file.empty()) {
    ev.timing = read_timing_json(timing_file);
    ev.timing_available = true;
  } else {
    ev.timing_note = in.bare_trajectory ? "not available: a bare trajectory file has no timing"
                                        : "not available: the run folder has no timing.json";
  }
  if (in.bare_trajectory) {
    ev.loop_closure_note = "not available: a bare trajectory file has no keyframes or graph";
  } else if (in.keyframes_file.empty()) {
    ev.loop_closure_note = "not available: the run folder has no keyframes.txt";
  } else if (graph_file.empty() && loops_file.empty()) {
    ev.loop_closure_note =
        "not available: the run folder has neither graph.json nor "
        "loop_closures.csv";
  } else {
    ev.loop_closures_available = true;
    ev.loop_closures_from_csv = graph_file.empty();
    ev.loop_closure_source = graph_file.empty()
                                 ? std::string(run_folder::kLoopClosures) +
                                       " (no graph.json: its rows are the loop edges, none pruned)"
                                 : std::string(run_folder::kGraph);
  }
  const RunIdentity identity =
      in.bare_trajectory ? RunIdentity{} : identity_of(in.run_dir / run_folder::kRun);
  // A run scored against the ground truth of another recording (another seed, say: every seed
  // has the same frame times) gives an error that measures nothing: refused, naming both.
  if (identity.recording) {
    const std::optional<DatasetRecording> truth = recording_of_dataset(dataset_dir);
    if (truth && !(*truth == *identity.recording)) {
      throw InvalidInputError(fmt::format(
          "{}: the run was made from the recording of {}, but {} holds the recording of {}; a "
          "run is scored against the ground truth of the dataset it ran on (to score its "
          "trajectory anyway, give {} instead of the run folder)",
          (in.run_dir / run_folder::kRun).string(), describe(*identity.recording),
          dataset_dir.string(), describe(*truth), in.trajectory_file.string()));
    }
  }
  ev.frontend = identity.frontend;
  ev.wifi_run = identity.wifi;
  ev.cost_model_s = identity.cost_model_s;
  ev.loop_closure_cost_s = identity.loop_closure_cost_s;
  ev.likelihood_posterior_cpu_s = identity.likelihood_posterior_cpu_s;
  ev.loop_query_s = identity.loop_query_s;
  if (input_file_present(dataset_dir / dataset::kCalibration, "the dataset's calibration")) {
    in.calibration = read_calibration_yaml(dataset_dir / dataset::kCalibration);
  }
  ev.intrinsics = in.calibration.intrinsics;
  in.clusters_file = in.run_dir / run_folder::kWifiClusters;
  // Our Wi-Fi runs always write their clusters; an external system's Wi-Fi variant may not.
  const bool external = identity.frontend.rfind(run_folder::kExternalFrontendPrefix, 0) == 0;
  if (ev.wifi_run &&
      (!external || input_file_present(in.clusters_file, "the run's Wi-Fi clusters"))) {
    required_file(in.run_dir, run_folder::kWifiClusters, "the Wi-Fi clusters run.json announces");
    ev.wifi_cluster_list = read_wifi_clusters_csv(in.clusters_file);
    ev.wifi_clusters = static_cast<std::int64_t>(ev.wifi_cluster_list.size());
  }
  return in;
}

/// ATE, RPE and the aligned path. Ground truth is associate.py's first list, the estimate its
/// second (with the offset), as evaluate_ate.py calls it: ties and repeated stamps go the same way.
/// `estimate_name` and `ground_truth_name` name the two in the error for too few shared stamps.
void score_trajectory(const Trajectory& ground_truth, const Trajectory& estimated,
                      std::int64_t offset_ns, const std::vector<Pose>& gt_poses,
                      const std::vector<double>& gt_path_m, const std::string& estimate_name,
                      const std::string& ground_truth_name, const EvalOptions& options,
                      RunEvaluation& ev) {
  const std::vector<AssociatedIndices> pairs = associate_by_time(
      times_of(ground_truth), times_of(estimated), options.max_time_difference_s, offset_ns);
  ev.frames_estimated = static_cast<std::int64_t>(estimated.size());
  ev.frames_ground_truth = static_cast<std::int64_t>(ground_truth.size());
  ev.frames_associated = static_cast<std::int64_t>(pairs.size());
  if (pairs.size() < kMinAssociatedPoses) {
    throw InvalidInputError(
        fmt::format("{} and {}: only {} poses share a timestamp (within {} s, estimate shifted "
                    "by {} s); need at least {} (is this the run of that dataset?)",
                    estimate_name, ground_truth_name, pairs.size(), options.max_time_difference_s,
                    options.time_offset_s, kMinAssociatedPoses));
  }
  std::vector<Pose> est_assoc, gt_assoc;
  for (const AssociatedIndices& a : pairs) {
    est_assoc.push_back(estimated[a.second].pose());
    gt_assoc.push_back(gt_poses[a.first]);
  }
  const AbsoluteTrajectoryError ate = absolute_trajectory_error(est_assoc, gt_assoc, options.align);
  ev.alignment = ate.alignment;
  ev.ate_rmse_m = ate.rmse_m;
  ev.ate_mean_m = ate.mean_m;
  ev.ate_median_m = ate.median_m;
  ev.ate_max_m = ate.max_m;
  const RelativePoseError rpe =
      relative_pose_error(est_assoc, gt_assoc, options.rpe_delta_m, ate.alignment.scale);
  ev.rpe_pairs = static_cast<std::int64_t>(rpe.pairs);
  ev.rpe_trans_per_m = rpe.translation_per_m;
  ev.rpe_rot_deg_per_m = rpe.rotation_deg_per_m;
  ev.rpe_trans_rmse_m = rpe.translation_rmse_m;
  ev.rpe_rot_rmse_deg = rpe.rotation_rmse_deg;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    PathSample s;
    s.time = ground_truth[pairs[i].first].time;
    s.ground_truth_m = gt_assoc[i].translation();
    s.estimated_aligned_m = ate.alignment.apply(Eigen::Vector3d(est_assoc[i].translation()));
    s.path_m = gt_path_m[pairs[i].first];
    s.error_m = ate.errors_m[i];
    ev.path.push_back(s);
  }
}

/// Each keyframe's ground truth (times on the dataset's clock); the Wi-Fi clusters must list
/// keyframes that exist.
void find_keyframe_truth(const RunInputs& in, const std::vector<Pose>& gt_poses,
                         const std::vector<double>& gt_path_m, const EvalOptions& options,
                         RunEvaluation& ev) {
  const std::vector<Timestamp> gt_times = times_of(in.ground_truth);
  for (std::size_t k = 0; k < in.keyframes.size(); ++k) {
    const Timestamp t = Timestamp::from_ns(in.keyframes[k].time.ns + in.offset_ns);
    const std::optional<std::size_t> g = nearest_stamp(gt_times, t, options.max_time_difference_s);
    if (!g) {
      throw ParseError(in.keyframes_file.string(), "",
                       fmt::format("keyframe {} at t = {} has no ground-truth pose within {} s", k,
                                   t.to_string(6), options.max_time_difference_s));
    }
    ev.keyframe_truth.push_back({t, gt_poses[*g], gt_path_m[*g]});
  }
  ev.keyframes = static_cast<std::int64_t>(in.keyframes.size());
  for (const WifiCluster& c : ev.wifi_cluster_list) {
    for (std::int64_t k : c.keyframes) {
      if (k >= ev.keyframes) {
        throw ParseError(in.clusters_file.string(), "keyframes",
                         fmt::format("cluster {} lists keyframe {}, keyframes.txt has {}", c.id, k,
                                     ev.keyframes));
      }
    }
  }
}

/// Verdicts on the accepted edges and the true revisits they miss (loop_closure_scoring.hpp).
void score_closures(const RunInputs& in, const fs::path& dataset_dir, const EvalOptions& options,
                    RunEvaluation& ev) {
  DatasetDepth depth(dataset_dir, in.calibration.intrinsics, in.calibration.depth_units_per_metre,
                     options);
  ev.loop_closure_score = score_loop_closures(
      ev.keyframe_truth, in.edges, [&depth](Timestamp t) { return depth.view(t); },
      in.calibration.intrinsics, options);
  const LoopClosureScore& s = ev.loop_closure_score;
  ev.loop_closures_detected = s.online.scored;
  ev.loop_closures_correct = s.online.correct;
  ev.false_positives = s.online.wrong_place;
  ev.false_positive_pct = s.online.false_positive_pct;
  ev.revisit_episodes = static_cast<std::int64_t>(s.episodes.size());
  ev.revisit_keyframes = s.revisit_keyframes;
  ev.false_negatives = s.online.false_negatives;
  ev.false_negative_pct = s.online.false_negative_pct;
  ev.overlap_used_depth = depth.available() && s.pairs_geometric_only == 0;
  if (!depth.available()) {
    ev.overlap_method =
        "geometric bound only: the dataset lists no depth images (no depth.txt: generated with "
        "--no-images, or not a dataset of ours)";
  } else if (s.pairs_geometric_only > 0) {
    ev.overlap_method = fmt::format(
        "depth test; {} of {} pairs geometric bound only (no depth image at their time)",
        s.pairs_geometric_only, s.pairs_tested);
  } else {
    ev.overlap_method = "depth test (ground-truth depth reprojection)";
  }
}

}  // namespace

RunEvaluation evaluate_run(const fs::path& input, const fs::path& dataset_dir,
                           const EvalOptions& options, bool verify_checksums) {
  validate(options);
  RunEvaluation ev;
  ev.run_dir = input.string();
  ev.dataset_dir = dataset_dir.string();
  ev.options = options;
  const RunInputs in = read_inputs(input, dataset_dir, options, verify_checksums, ev);

  const std::vector<Pose> gt_poses = poses_of(in.ground_truth);
  const std::vector<double> gt_path_m = cumulative_path_length_m(gt_poses);
  score_trajectory(in.ground_truth, in.estimated, in.offset_ns, gt_poses, gt_path_m,
                   in.trajectory_file.string(), (dataset_dir / dataset::kGroundTruth).string(),
                   options, ev);
  find_keyframe_truth(in, gt_poses, gt_path_m, options, ev);
  if (ev.loop_closures_available) score_closures(in, dataset_dir, options, ev);

  // Time.
  ev.loop_closure_detection_s = ev.timing.loop_closure_detection_s;
  ev.wifi_overhead_s = ev.timing.wifi_overhead_s;
  ev.optimisation_s = ev.timing.optimisation_s;
  ev.total_s = ev.timing.total_s;
  ev.wall_s = ev.timing.wall_s;
  ev.candidate_comparisons = ev.timing.counter(run_folder::counter::kCandidateComparisons);
  return ev;
}

RunEvaluation evaluate_trajectory(const Trajectory& estimated, const Trajectory& ground_truth,
                                  const EvalOptions& options, const std::string& estimate_name,
                                  const std::string& ground_truth_name) {
  validate(options);
  RunEvaluation ev;
  ev.run_dir = estimate_name;
  ev.dataset_dir = ground_truth_name;
  ev.options = options;
  ev.loop_closure_note = "not available: a trajectory has no keyframes or graph";
  ev.timing_note = "not available: a trajectory has no timing";
  const std::vector<Pose> gt_poses = poses_of(ground_truth);
  score_trajectory(ground_truth, estimated, Timestamp::from_seconds_exact(options.time_offset_s).ns,
                   gt_poses, cumulative_path_length_m(gt_poses), estimate_name, ground_truth_name,
                   options, ev);
  return ev;
}

}  // namespace wifislam::eval
