#pragma once
// The result of evaluating one SLAM run against its dataset's exact ground truth: the paper's
// metrics (trajectory RMSE, false positive / false negative loop closures, loop-closure time and
// Wi-Fi overhead) plus everything needed to explain them (per-closure verdicts, revisit
// episodes, the aligned path for plots) and the thresholds used.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include "core/camera_intrinsics.hpp"
#include "core/timestamp.hpp"
#include "eval/alignment.hpp"
#include "eval/eval_options.hpp"
#include "eval/loop_closure_scoring.hpp"
#include "eval/timing_table.hpp"
#include "eval/wifi_clusters_csv.hpp"

namespace wifislam::eval {

/// One associated frame: ground truth, the aligned estimate and the error between them.
struct PathSample {
  Timestamp time;
  Eigen::Vector3d ground_truth_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d estimated_aligned_m = Eigen::Vector3d::Zero();
  double path_m = 0.0;  // ground-truth path length from the first ground-truth pose
  double error_m = 0.0;
};

struct RunEvaluation {
  std::string run_dir, dataset_dir;
  std::string frontend;   // from run.json, "" when absent
  bool wifi_run = false;  // run.json's "wifi" (false when absent)
  /// The front end's deterministic time (rtabmap's cost model, summed over nodes), when run.json
  /// has one: independent of machine load, unlike the wall-clock times below.
  std::optional<double> cost_model_s;
  /// RTAB-Map's loop-closure detection time (likelihood, posterior and the loop hypothesis'
  /// verification, as Rtabmap::process times them), when run.json has it: its cost-model share,
  /// and the measured thread CPU of likelihood and posterior (the verification's measured time is
  /// timing.roles["long_term"]).
  std::optional<double> loop_closure_cost_s, likelihood_posterior_cpu_s;
  /// ORB-SLAM's loop query time (DetectLoop and SearchByBoW, measured), when run.json has it;
  /// its verifications are timing.roles["long_term"].
  std::optional<double> loop_query_s;
  EvalOptions options;

  // Trajectory error (ATE after alignment, RPE per metre travelled).
  std::int64_t frames_estimated = 0, frames_ground_truth = 0, frames_associated = 0;
  double ate_rmse_m = 0.0, ate_mean_m = 0.0, ate_median_m = 0.0, ate_max_m = 0.0;
  Alignment alignment;
  std::int64_t rpe_pairs = 0;
  double rpe_trans_per_m = 0.0;    // mean |translation error| / path length over delta pairs
  double rpe_rot_deg_per_m = 0.0;  // mean rotation error [deg] / path length over delta pairs
  double rpe_trans_rmse_m = 0.0;   // RMSE of the translation errors over rpe_delta_m
  double rpe_rot_rmse_deg = 0.0;

  // Loop closures. Available with keyframes.txt and graph.json or loop_closures.csv; the
  // scalars below are the online set (every scored edge as accepted; the paper's numbers), the
  // after-pruning set is in loop_closure_score.after_pruning.
  bool loop_closures_available = false;
  std::string loop_closure_source;  // "graph.json", or loop_closures.csv and why
  std::string loop_closure_note;    // why not available
  std::int64_t loop_closure_csv_rows = 0;
  // Without graph.json the csv's rows are the scored edges. A row naming the keyframe pair of an
  // earlier row (in either order) is the same closure reported again (two stamps of an external
  // system's closures that fall on one keyframe pair, say): scored once, as its first row, and
  // counted here so that a system is neither charged twice for one wrong closure nor credited
  // twice for one correct one.
  bool loop_closures_from_csv = false;
  std::int64_t loop_closure_csv_repeated_rows = 0;
  std::int64_t loop_closures_detected = 0, loop_closures_correct = 0, false_positives = 0;
  double false_positive_pct = 0.0;
  std::int64_t revisit_episodes = 0, revisit_keyframes = 0, false_negatives = 0;
  double false_negative_pct = 0.0;
  bool overlap_used_depth = false;
  std::string overlap_method;  // how views were judged (depth test, or geometric bound only)

  // Time (seconds, wall-clock of the run) and work, from timing.json when there is one.
  bool timing_available = false;
  std::string timing_note;  // why not available
  double loop_closure_detection_s = 0.0, wifi_overhead_s = 0.0, optimisation_s = 0.0;
  double total_s = 0.0, wall_s = 0.0;
  std::int64_t keyframes = 0, candidate_comparisons = 0;
  std::int64_t wifi_clusters = 0;

  // Details.
  TimingTable timing;
  LoopClosureScore loop_closure_score;
  std::vector<KeyframeTruth> keyframe_truth;
  std::vector<PathSample> path;
  std::vector<WifiCluster> wifi_cluster_list;
  CameraIntrinsics intrinsics;

  /// Everything (thresholds, metrics, timing, per-closure verdicts, episodes); no per-frame data.
  nlohmann::json to_json() const;
  nlohmann::ordered_json to_ordered_json() const;
  /// One flat level of scalars: the metrics.csv row (thresholds and counters included).
  nlohmann::ordered_json flat_metrics() const;
  /// Every column a metrics.csv row can have, whatever the run holds (a trajectory file's row has
  /// no loop-closure columns; a run folder's has them). Counters are named by the run itself.
  static std::vector<std::string> flat_metric_names();
};

}  // namespace wifislam::eval
