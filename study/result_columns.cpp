#include "study/result_columns.hpp"

#include <cstdint>
#include <optional>

#include "core/run_format.hpp"

namespace wifislam::study {

namespace {

SqlValue count(std::int64_t v) { return v; }
SqlValue optional_value(const std::optional<double>& v) { return v ? SqlValue(*v) : SqlValue(); }

/// The verifications of the long-term candidates: the ones Wi-Fi bounds.
eval::RoleTiming long_term(const eval::RunEvaluation& e) {
  const auto lt = e.timing.roles.find("long_term");
  return lt == e.timing.roles.end() ? eval::RoleTiming{} : lt->second;
}

}  // namespace

double paper_loop_closure_s(const eval::RunEvaluation& e) {
  const double verification_s = long_term(e).time_s;
  if (e.likelihood_posterior_cpu_s) return *e.likelihood_posterior_cpu_s + verification_s;
  if (e.loop_query_s) return *e.loop_query_s + verification_s + e.optimisation_s;
  return e.timing.candidate_selection_s + verification_s + e.optimisation_s;
}

const std::vector<StudyColumn<RadioResolution>>& radio_metric_columns() {
  using R = RadioResolution;
  static const std::vector<StudyColumn<R>> columns = {
      {"pauses", [](const R& r) { return count(r.pauses); }},
      {"pairs", [](const R& r) { return count(r.pairs); }},
      {"resolution_m", [](const R& r) { return optional_value(r.resolution_m); }},
      {"near_similar_share", [](const R& r) { return SqlValue(r.near_similar_share); }},
      {"far_similar_share", [](const R& r) { return SqlValue(r.far_similar_share); }},
      {"clusters", [](const R& r) { return count(r.clusters); }},
      {"aps_heard_per_pause", [](const R& r) { return SqlValue(r.aps_heard_per_pause); }},
  };
  return columns;
}

const std::vector<StudyColumn<eval::RunEvaluation>>& slam_metric_columns() {
  using E = eval::RunEvaluation;
  static const std::vector<StudyColumn<E>> columns = {
      {"ate_rmse_m", [](const E& e) { return SqlValue(e.ate_rmse_m); }},
      {"frames", [](const E& e) { return count(e.frames_ground_truth); }},
      {"keyframes", [](const E& e) { return count(e.keyframes); }},
      {"loop_closures", [](const E& e) { return count(e.loop_closures_detected); }},
      {"scored_closures", [](const E& e) { return count(e.loop_closure_score.online.scored); }},
      {"correct_closures", [](const E& e) { return count(e.loop_closure_score.online.correct); }},
      {"right_place_imprecise",
       [](const E& e) { return count(e.loop_closure_score.online.right_place_imprecise); }},
      {"wrong_place_closures",
       [](const E& e) { return count(e.loop_closure_score.online.wrong_place); }},
      {"far_wrong_place_closures",
       [](const E& e) { return count(e.loop_closure_score.online.far_wrong_place); }},
      {"false_positive_pct",
       [](const E& e) { return SqlValue(e.loop_closure_score.online.false_positive_pct); }},
      {"revisit_episodes", [](const E& e) { return count(e.revisit_episodes); }},
      {"false_negatives",
       [](const E& e) { return count(e.loop_closure_score.online.false_negatives); }},
      {"false_negative_pct",
       [](const E& e) { return SqlValue(e.loop_closure_score.online.false_negative_pct); }},
      {"wrong_place_after_pruning",
       [](const E& e) { return count(e.loop_closure_score.after_pruning.wrong_place); }},
      {"far_wrong_place_after_pruning",
       [](const E& e) { return count(e.loop_closure_score.after_pruning.far_wrong_place); }},
      {"false_negatives_after_pruning",
       [](const E& e) { return count(e.loop_closure_score.after_pruning.false_negatives); }},
      {"candidate_comparisons", [](const E& e) { return count(e.candidate_comparisons); }},
      {"long_term_comparisons", [](const E& e) { return count(long_term(e).comparisons); }},
      {"wifi_clusters", [](const E& e) { return count(e.wifi_clusters); }},
      {"cost_model_s", [](const E& e) { return optional_value(e.cost_model_s); }},
      {"loop_closure_cost_s", [](const E& e) { return optional_value(e.loop_closure_cost_s); }},
      {"optimisations",
       [](const E& e) { return count(e.timing.counter(run_folder::counter::kOptimisations)); }},
      {"optimisation_iterations",
       [](const E& e) {
         return count(e.timing.counter(run_folder::counter::kOptimisationIterations));
       }},
  };
  return columns;
}

const std::vector<StudyColumn<eval::RunEvaluation>>& slam_timing_columns() {
  using E = eval::RunEvaluation;
  static const std::vector<StudyColumn<E>> columns = {
      {"loop_closure_detection_s", [](const E& e) { return SqlValue(e.loop_closure_detection_s); }},
      {"bounded_module_s",
       [](const E& e) {
         return SqlValue(e.timing.candidate_selection_s + long_term(e).time_s + e.optimisation_s);
       }},
      {"paper_loop_closure_s", [](const E& e) { return SqlValue(paper_loop_closure_s(e)); }},
      {"candidate_selection_s",
       [](const E& e) { return SqlValue(e.timing.candidate_selection_s); }},
      {"long_term_verification_s", [](const E& e) { return SqlValue(long_term(e).time_s); }},
      {"optimisation_s", [](const E& e) { return SqlValue(e.optimisation_s); }},
      {"wifi_overhead_s", [](const E& e) { return SqlValue(e.wifi_overhead_s); }},
      {"total_s", [](const E& e) { return SqlValue(e.total_s); }},
      {"wall_s", [](const E& e) { return SqlValue(e.wall_s); }},
  };
  return columns;
}

}  // namespace wifislam::study
