#include "eval/run_evaluation.hpp"

#include <utility>

namespace wifislam::eval {

nlohmann::ordered_json RunEvaluation::flat_metrics() const {
  nlohmann::ordered_json j;
  j["run_dir"] = run_dir;
  j["dataset_dir"] = dataset_dir;
  j["frontend"] = frontend;
  j["wifi_run"] = wifi_run;
  if (cost_model_s) j["cost_model_s"] = *cost_model_s;
  if (loop_closure_cost_s) j["loop_closure_cost_s"] = *loop_closure_cost_s;
  if (likelihood_posterior_cpu_s) j["likelihood_posterior_cpu_s"] = *likelihood_posterior_cpu_s;
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
  j["loop_closures_available"] = loop_closures_available;
  if (loop_closures_available) {
    j["loop_closure_source"] = loop_closure_source;
    j["loop_closure_csv_rows"] = loop_closure_csv_rows;
    const LoopClosureScore& s = loop_closure_score;
    j["loop_edges_considered"] = s.edges_considered;
    j["loop_edges_short_path"] = s.edges_short_path;
    for (const auto& [prefix, counts] :
         {std::pair{"online_", &s.online}, std::pair{"pruned_", &s.after_pruning}}) {
      const nlohmann::ordered_json values = counts->to_json();  // outlives the loop below
      for (const auto& [name, value] : values.items()) j[prefix + name] = value;
    }
    j["revisit_episodes"] = revisit_episodes;
    j["revisit_keyframes"] = revisit_keyframes;
    j["overlap_used_depth"] = overlap_used_depth;
    j["overlap_method"] = overlap_method;
    j["overlap_pairs_tested"] = s.pairs_tested;
    j["overlap_pairs_geometric_only"] = s.pairs_geometric_only;
  }
  j["timing_available"] = timing_available;
  if (timing_available) {
    j["loop_closure_detection_s"] = loop_closure_detection_s;
    j["wifi_overhead_s"] = wifi_overhead_s;
    j["optimisation_s"] = optimisation_s;
    j["total_s"] = total_s;
    j["wall_s"] = wall_s;
    j["candidate_comparisons"] = candidate_comparisons;
    for (const auto& [name, value] : timing.counters) j["counter." + name] = value;
  }
  j["keyframes"] = keyframes;
  j["wifi_clusters"] = wifi_clusters;
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
  if (cost_model_s) j["cost_model_s"] = *cost_model_s;
  if (loop_closure_cost_s) j["loop_closure_cost_s"] = *loop_closure_cost_s;
  if (likelihood_posterior_cpu_s) j["likelihood_posterior_cpu_s"] = *likelihood_posterior_cpu_s;
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
       {{"mode", eval::to_string(options.align)},
        {"scale", alignment.scale},
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
  lc["available"] = loop_closures_available;
  if (!loop_closures_available) {
    lc["note"] = loop_closure_note;
  } else {
    const LoopClosureScore& s = loop_closure_score;
    lc["source"] = loop_closure_source;
    lc["loop_closure_csv_rows"] = loop_closure_csv_rows;
    lc["edges_considered"] = s.edges_considered;
    lc["edges_short_path"] = s.edges_short_path;
    lc["online"] = s.online.to_json();
    lc["pruned"] = s.after_pruning.to_json();
    lc["revisit_episodes"] = revisit_episodes;
    lc["revisit_keyframes"] = revisit_keyframes;
    lc["overlap_method"] = overlap_method;
    lc["overlap_used_depth"] = overlap_used_depth;
    lc["overlap_pairs_tested"] = s.pairs_tested;
    lc["overlap_pairs_geometric_only"] = s.pairs_geometric_only;
    lc["closures"] = nlohmann::ordered_json::array();
    for (const ScoredLoopClosure& c : s.closures)
      lc["closures"].push_back(eval::to_json(c, keyframe_truth));
    lc["episodes"] = nlohmann::ordered_json::array();
    for (const RevisitEpisode& e : s.episodes) lc["episodes"].push_back(eval::to_json(e));
  }
  j["loop_closures"] = lc;
  nlohmann::ordered_json time;
  time["available"] = timing_available;
  if (!timing_available) {
    time["note"] = timing_note;
  } else {
    time.update(timing.to_json());
    time["candidate_comparisons"] = candidate_comparisons;
  }
  time["keyframes"] = keyframes;
  j["timing"] = time;
  j["wifi_clusters"] = wifi_clusters;
  return j;
}

nlohmann::json RunEvaluation::to_json() const {
  return nlohmann::json::parse(to_ordered_json().dump());
}

}  // namespace wifislam::eval
