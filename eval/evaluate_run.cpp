#include "eval/evaluate_run.hpp"

#include <fstream>

#include <fmt/format.h>

#include "core/dataset_calibration.hpp"
#include "core/dataset_format.hpp"
#include "core/dataset_reader.hpp"
#include "core/error.hpp"
#include "core/run_format.hpp"
#include "core/tum_trajectory.hpp"
#include "eval/association.hpp"
#include "eval/dataset_depth.hpp"
#include "eval/loop_closure_csv.hpp"
#include "eval/trajectory_error.hpp"

namespace wifislam::eval {

namespace fs = std::filesystem;

namespace {

fs::path required_file(const fs::path& folder, const char* name, const char* what) {
  const fs::path p = folder / name;
  if (!fs::is_regular_file(p)) throw IoError(fmt::format("{}: missing ({})", p.string(), what));
  return p;
}

std::vector<Timestamp> times_of(const Trajectory& t) {
  std::vector<Timestamp> out;
  out.reserve(t.size());
  for (const StampedPose& p : t) out.push_back(p.time);
  return out;
}

/// What run.json says about the run: the front end and whether the Wi-Fi module ran. A folder
/// without run.json (a run written by another tool) is a run without Wi-Fi of an unnamed front
/// end. Format version 1 (before "wifi" existed) named a Wi-Fi run "<frontend>+wifi".
struct RunIdentity {
  std::string frontend;
  bool wifi = false;
};

RunIdentity identity_of(const fs::path& run_json) {
  namespace key = run_folder::run_key;
  RunIdentity id;
  if (!fs::is_regular_file(run_json)) return id;
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
  return id;
}

}  // namespace

RunEvaluation evaluate_run(const fs::path& run_dir, const fs::path& dataset_dir,
                           const EvalOptions& options) {
  validate(options);
  if (!fs::is_directory(run_dir)) throw IoError(run_dir.string() + ": run folder not found");
  if (!fs::is_directory(dataset_dir)) {
    throw IoError(dataset_dir.string() + ": dataset folder not found");
  }
  RunEvaluation ev;
  ev.run_dir = run_dir.string();
  ev.dataset_dir = dataset_dir.string();
  ev.options = options;

  // Inputs (everything read and checked before anything is computed or written).
  required_file(dataset_dir, dataset::kGroundTruth, "the dataset's ground truth");
  const Trajectory ground_truth = read_ground_truth(dataset_dir);
  const fs::path trajectory_file =
      required_file(run_dir, run_folder::kTrajectory, "the run's estimated trajectory");
  const fs::path keyframes_file =
      required_file(run_dir, run_folder::kKeyframes, "the run's keyframes");
  const fs::path loops_file =
      required_file(run_dir, run_folder::kLoopClosures, "the run's loop closures");
  const fs::path timing_file = required_file(run_dir, run_folder::kTiming, "the run's timing");
  const Trajectory estimated = read_tum_trajectory(trajectory_file.string());
  const Trajectory keyframes = read_tum_trajectory(keyframes_file.string());
  const std::vector<DetectedLoopClosure> loops = read_loop_closures_csv(loops_file);
  ev.timing = read_timing_json(timing_file);
  const RunIdentity identity = identity_of(run_dir / run_folder::kRun);
  ev.frontend = identity.frontend;
  ev.wifi_run = identity.wifi;
  DatasetCalibration calibration;
  if (fs::exists(dataset_dir / dataset::kCalibration)) {
    calibration = read_calibration_yaml(dataset_dir / dataset::kCalibration);
  }
  ev.intrinsics = calibration.intrinsics;
  const fs::path clusters_file = run_dir / run_folder::kWifiClusters;
  if (ev.wifi_run) {
    required_file(run_dir, run_folder::kWifiClusters, "the Wi-Fi clusters run.json announces");
    ev.wifi_cluster_list = read_wifi_clusters_csv(clusters_file);
    ev.wifi_clusters = static_cast<std::int64_t>(ev.wifi_cluster_list.size());
  }

  // Ground truth with its path length.
  std::vector<Pose> gt_poses;
  gt_poses.reserve(ground_truth.size());
  for (const StampedPose& p : ground_truth) gt_poses.push_back(p.pose());
  const std::vector<double> gt_path_m = cumulative_path_length_m(gt_poses);
  const std::vector<Timestamp> gt_times = times_of(ground_truth);

  // Trajectory error.
  const std::vector<AssociatedIndices> pairs =
      associate_by_time(times_of(estimated), gt_times, options.max_time_difference_s);
  ev.frames_estimated = static_cast<std::int64_t>(estimated.size());
  ev.frames_ground_truth = static_cast<std::int64_t>(ground_truth.size());
  ev.frames_associated = static_cast<std::int64_t>(pairs.size());
  if (pairs.size() < 3) {
    throw InvalidInputError(
        fmt::format("{} and {}: only {} poses share a timestamp (within {} s); need at least 3 "
                    "(is this the run of that dataset?)",
                    trajectory_file.string(), (dataset_dir / dataset::kGroundTruth).string(),
                    pairs.size(), options.max_time_difference_s));
  }
  std::vector<Pose> est_assoc, gt_assoc;
  for (const AssociatedIndices& a : pairs) {
    est_assoc.push_back(estimated[a.first].pose());
    gt_assoc.push_back(gt_poses[a.second]);
  }
  const AbsoluteTrajectoryError ate =
      absolute_trajectory_error(est_assoc, gt_assoc, options.align_scale);
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
    s.time = ground_truth[pairs[i].second].time;
    s.ground_truth_m = gt_assoc[i].translation();
    s.estimated_aligned_m = ate.alignment.apply(Eigen::Vector3d(est_assoc[i].translation()));
    s.path_m = gt_path_m[pairs[i].second];
    s.error_m = ate.errors_m[i];
    ev.path.push_back(s);
  }

  // Keyframes with their ground truth.
  for (std::size_t k = 0; k < keyframes.size(); ++k) {
    const std::optional<std::size_t> g =
        nearest_stamp(gt_times, keyframes[k].time, options.max_time_difference_s);
    if (!g) {
      throw ParseError(keyframes_file.string(), "",
                       fmt::format("keyframe {} at t = {} has no ground-truth pose within {} s", k,
                                   keyframes[k].time.to_string(6), options.max_time_difference_s));
    }
    ev.keyframe_truth.push_back({keyframes[k].time, gt_poses[*g], gt_path_m[*g]});
  }
  ev.keyframes = static_cast<std::int64_t>(keyframes.size());
  for (const WifiCluster& c : ev.wifi_cluster_list) {
    for (std::int64_t k : c.keyframes) {
      if (k >= ev.keyframes) {
        throw ParseError(clusters_file.string(), "keyframes",
                         fmt::format("cluster {} lists keyframe {}, keyframes.txt has {}", c.id, k,
                                     ev.keyframes));
      }
    }
  }

  // Loop closures.
  DatasetDepth depth(dataset_dir, calibration.intrinsics, calibration.depth_units_per_metre,
                     options);
  ev.loop_closure_score = score_loop_closures(
      ev.keyframe_truth, loops, loops_file.string(),
      [&depth](Timestamp t) { return depth.view(t); }, calibration.intrinsics, options);
  const LoopClosureScore& s = ev.loop_closure_score;
  ev.loop_closures_detected = s.detected;
  ev.loop_closures_correct = s.correct;
  ev.false_positives = s.false_positives;
  ev.false_positive_pct = s.false_positive_pct;
  ev.revisit_episodes = static_cast<std::int64_t>(s.episodes.size());
  ev.revisit_keyframes = s.revisit_keyframes;
  ev.false_negatives = s.false_negatives;
  ev.false_negative_pct = s.false_negative_pct;
  ev.overlap_used_depth = depth.available() && s.pairs_geometric_only == 0;
  if (!depth.available()) {
    ev.overlap_method =
        "geometric bound only: the dataset has no depth images (generated with --no-images)";
  } else if (s.pairs_geometric_only > 0) {
    ev.overlap_method = fmt::format(
        "depth test; {} of {} pairs geometric bound only (no depth image at their time)",
        s.pairs_geometric_only, s.pairs_tested);
  } else {
    ev.overlap_method = "depth test (ground-truth depth reprojection)";
  }

  // Time.
  ev.loop_closure_detection_s = ev.timing.loop_closure_detection_s;
  ev.wifi_overhead_s = ev.timing.wifi_overhead_s;
  ev.optimisation_s = ev.timing.optimisation_s;
  ev.total_s = ev.timing.total_s;
  ev.wall_s = ev.timing.wall_s;
  ev.candidate_comparisons = ev.timing.counter(run_folder::counter::kCandidateComparisons);
  return ev;
}

}  // namespace wifislam::eval
