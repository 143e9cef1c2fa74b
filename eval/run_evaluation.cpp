#include "eval/run_evaluation.hpp"

namespace wifislam::eval {

nlohmann::ordered_json RunEvaluation::flat_metrics() const {
  nlohmann::ordered_json j;
  j["run_dir"] = run_dir;
  j["dataset_dir"] = dataset_dir;
  j["frontend"] = frontend;
  j["wifi_run"] = wifi_run;
  j["frames_estimated"] = frames_estimated;
  j["frames_ground_truth"] = frames_ground_truth;
  j["frames_associated"] = frames_associated;
  j["ate_rmse_m"] = ate_rmse_m;
  j["ate_mean_m"] = ate_mean_m;
  j["ate_median_m"] = ate_median_m;
  j["ate_max_m"] = ate_max_m;
  j["alignment_scale"] = alignment.scale;
  j["rpe_pairs"] = rpe_pairs;
  j["rpe_trans_per_m"] = rpe_trans_per_m;
  j["rpe_rot_deg_per_m"] = rpe_rot_deg_per_m;
  j["rpe_trans_rmse_m"] = rpe_trans_rmse_m;
  j["rpe_rot_rmse_deg"] = rpe_rot_rmse_deg;
  j["loop_closures_detected"] = loop_closures_detected;
  j["loop_closures_correct"] = loop_closures_correct;
  j["false_positives"] = false_positives;
  j["false_positive_pct"] = false_positive_pct;
  j["revisit_episodes"] = revisit_episodes;
  j["revisit_keyframes"] = revisit_keyframes;
  j["false_negatives"] = false_negatives;
  j["false_negative_pct"] = false_negative_pct;
  j["overlap_used_depth"] = overlap_used_depth;
  j["overlap_method"] = overlap_method;
  j["overlap_pairs_tested"] = loop_closure_score.pairs_tested;
  j["overlap_pairs_geometric_only"] = loop_closure_score.pairs_geometric_only;
  j["loop_closure_detection_s"] = loop_closure_detection_s;
  j["wifi_overhead_s"] = wifi_overhead_s;
  j["optimisation_s"] = optimisation_s;
  j["total_s"] = total_s;
  j["wall_s"] = wall_s;
  j["keyframes"] = keyframes;
  j["candidate_comparisons"] = candidate_comparisons;
  j["wifi_clusters"] = wifi_clusters;
  for (const auto& [name, value] : timing.counters) j["counter." + name] = value;
  const nlohmann::ordered_json thresholds = options.to_json();
  for (const auto& [name, value] : thresholds.items()) j["threshold." + name] = value;
  return j;
}

nlohmann::ordered_json RunEvaluation::to_ordered_json() const {
  nlohmann::ordered_json j;
  j["run_dir"] = run_dir;
  j["dataset_dir"] = dataset_dir;
  j["frontend"] = frontend;
  j["wifi_run"] = wifi_run;
  j["thresholds"] = options.to_json();
  j["trajectory"] = {
      {"frames_estimated", frames_estimated},
      {"frames_ground_truth", frames_ground_truth},
      {"frames_associated", frames_associated},
      {"ate_rmse_m", ate_rmse_m},
      {"ate_mean_m", ate_mean_m},
      {"ate_median_m", ate_median_m},
      {"ate_max_m", ate_max_m},
      {"alignment",
       {{"scale", alignment.scale},
        {"rotation_row_major",
         {alignment.rotation(0, 0), alignment.rotation(0, 1), alignment.rotation(0, 2),
          alignment.rotation(1, 0), alignment.rotation(1, 1), alignment.rotation(1, 2),
          alignment.rotation(2, 0), alignment.rotation(2, 1), alignment.rotation(2, 2)}},
        {"translation_m",
         {alignment.translation_m.x(), alignment.translation_m.y(), alignment.translation_m.z()}}}},
      {"rpe_pairs", rpe_pairs},
      {"rpe_trans_per_m", rpe_trans_per_m},
      {"rpe_rot_deg_per_m", rpe_rot_deg_per_m},
      {"rpe_trans_rmse_m", rpe_trans_rmse_m},
      {"rpe_rot_rmse_deg", rpe_rot_rmse_deg}};
  nlohmann::ordered_json lc;
  lc["detected"] = loop_closures_detected;
  lc["correct"] = loop_closures_correct;
  lc["false_positives"] = false_positives;
  lc["false_positive_pct"] = false_positive_pct;
  lc["revisit_episodes"] = revisit_episodes;
  lc["revisit_keyframes"] = revisit_keyframes;
  lc["false_negatives"] = false_negatives;
  lc["false_negative_pct"] = false_negative_pct;
  lc["overlap_method"] = overlap_method;
  lc["overlap_used_depth"] = overlap_used_depth;
  lc["overlap_pairs_tested"] = loop_closure_score.pairs_tested;
  lc["overlap_pairs_geometric_only"] = loop_closure_score.pairs_geometric_only;
  lc["closures"] = nlohmann::ordered_json::array();
  for (const ScoredLoopClosure& c : loop_closure_score.closures)
    lc["closures"].push_back(eval::to_json(c));
  lc["episodes"] = nlohmann::ordered_json::array();
  for (const RevisitEpisode& e : loop_closure_score.episodes)
    lc["episodes"].push_back(eval::to_json(e));
  j["loop_closures"] = lc;
  nlohmann::ordered_json time = timing.to_json();
  time["keyframes"] = keyframes;
  time["candidate_comparisons"] = candidate_comparisons;
  j["timing"] = time;
  j["wifi_clusters"] = wifi_clusters;
  return j;
}

nlohmann::json RunEvaluation::to_json() const {
  return nlohmann::json::parse(to_ordered_json().dump());
}

}  // namespace wifislam::eval
