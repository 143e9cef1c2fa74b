#include "eval/run_evaluation.hpp"

#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace wifislam::eval {

namespace {

using Json = nlohmann::ordered_json;
using E = RunEvaluation;

// The evaluation's metrics, listed once, with where each appears: in the flat row (metrics.csv,
// comparison.csv: a key, or a prefix before each key of an object's items) and in the sections of
// metrics.json (a key, or an object whose items join the section). Both forms follow the table's
// order; where they place a value apart (the thresholds, overlap_used_depth) it has two entries.

enum class Flat { kNone, kKey, kPrefixed };
enum class Nested { kNone, kKey, kMerged };

struct Metric {
  Flat flat;
  const char* flat_name;  // key or prefix
  Nested nested;
  const char* section;  // "" top level
  const char* nested_name;
  bool (*present)(const E&);
  Json (*value)(const E&);
  Json (*nested_value)(const E&) = nullptr;  // when metrics.json shows more than the flat row
};

bool always(const E&) { return true; }
bool with_closures(const E& e) { return e.loop_closures_available; }
bool without_closures(const E& e) { return !e.loop_closures_available; }
bool with_closures_from_csv(const E& e) {
  return e.loop_closures_available && e.loop_closures_from_csv;
}
bool with_timing(const E& e) { return e.timing_available; }
bool without_timing(const E& e) { return !e.timing_available; }

/// A metric in both forms under one name.
Metric both(const char* section, const char* name, bool (*present)(const E&),
            Json (*value)(const E&)) {
  return {Flat::kKey, name, Nested::kKey, section, name, present, value};
}

/// An RPE figure, or null when no pair was measured.
Json rpe_json(const E& e, double value) { return e.rpe_pairs > 0 ? Json(value) : Json(nullptr); }

Json alignment_json(const E& e) {
  const Alignment& a = e.alignment;
  return {
      {"mode", eval::to_string(e.options.align)},
      {"scale", a.scale},
      {"rotation_row_major",
       {a.rotation(0, 0), a.rotation(0, 1), a.rotation(0, 2), a.rotation(1, 0), a.rotation(1, 1),
        a.rotation(1, 2), a.rotation(2, 0), a.rotation(2, 1), a.rotation(2, 2)}},
      {"translation_m", {a.translation_m.x(), a.translation_m.y(), a.translation_m.z()}}};
}

Json closures_json(const E& e) {
  Json out = Json::array();
  for (const ScoredLoopClosure& c : e.loop_closure_score.closures)
    out.push_back(eval::to_json(c, e.keyframe_truth));
  return out;
}

Json episodes_json(const E& e) {
  Json out = Json::array();
  for (const RevisitEpisode& r : e.loop_closure_score.episodes) out.push_back(eval::to_json(r));
  return out;
}

Json counters_json(const E& e) {
  Json out = Json::object();
  for (const auto& [name, value] : e.timing.counters) out[name] = value;
  return out;
}

const std::vector<Metric>& metric_list() {
  static const std::vector<Metric> list = {
      both("", "run_dir", always, [](const E& e) { return Json(e.run_dir); }),
      both("", "dataset_dir", always, [](const E& e) { return Json(e.dataset_dir); }),
      both("", "frontend", always, [](const E& e) { return Json(e.frontend); }),
      both("", "wifi_run", always, [](const E& e) { return Json(e.wifi_run); }),
      both(
          "", "cost_model_s", [](const E& e) { return e.cost_model_s.has_value(); },
          [](const E& e) { return Json(*e.cost_model_s); }),
      both(
          "", "loop_closure_cost_s", [](const E& e) { return e.loop_closure_cost_s.has_value(); },
          [](const E& e) { return Json(*e.loop_closure_cost_s); }),
      both(
          "", "likelihood_posterior_cpu_s",
          [](const E& e) { return e.likelihood_posterior_cpu_s.has_value(); },
          [](const E& e) { return Json(*e.likelihood_posterior_cpu_s); }),
      both(
          "", "loop_query_s", [](const E& e) { return e.loop_query_s.has_value(); },
          [](const E& e) { return Json(*e.loop_query_s); }),
      {Flat::kNone, "", Nested::kKey, "", "thresholds", always,
       [](const E& e) { return e.options.to_json(); }},
      // Trajectory error.
      both("trajectory", "frames_estimated", always,
           [](const E& e) { return Json(e.frames_estimated); }),
      both("trajectory", "frames_ground_truth", always,
           [](const E& e) { return Json(e.frames_ground_truth); }),
      both("trajectory", "frames_associated", always,
           [](const E& e) { return Json(e.frames_associated); }),
      both("trajectory", "ate_rmse_m", always, [](const E& e) { return Json(e.ate_rmse_m); }),
      both("trajectory", "ate_mean_m", always, [](const E& e) { return Json(e.ate_mean_m); }),
      both("trajectory", "ate_median_m", always, [](const E& e) { return Json(e.ate_median_m); }),
      both("trajectory", "ate_max_m", always, [](const E& e) { return Json(e.ate_max_m); }),
      {Flat::kKey, "alignment_scale", Nested::kKey, "trajectory", "alignment", always,
       [](const E& e) { return Json(e.alignment.scale); }, alignment_json},
      both("trajectory", "rpe_pairs", always, [](const E& e) { return Json(e.rpe_pairs); }),
      // No pair rpe_delta_m apart (a route shorter than that, or a robot standing still): the
      // RPE is not measured, null rather than a 0 that a --require would take for perfect.
      both("trajectory", "rpe_trans_per_m", always,
           [](const E& e) { return rpe_json(e, e.rpe_trans_per_m); }),
      both("trajectory", "rpe_rot_deg_per_m", always,
           [](const E& e) { return rpe_json(e, e.rpe_rot_deg_per_m); }),
      both("trajectory", "rpe_trans_rmse_m", always,
           [](const E& e) { return rpe_json(e, e.rpe_trans_rmse_m); }),
      both("trajectory", "rpe_rot_rmse_deg", always,
           [](const E& e) { return rpe_json(e, e.rpe_rot_rmse_deg); }),
      // Loop closures.
      {Flat::kKey, "loop_closures_available", Nested::kKey, "loop_closures", "available", always,
       [](const E& e) { return Json(e.loop_closures_available); }},
      {Flat::kNone, "", Nested::kKey, "loop_closures", "note", without_closures,
       [](const E& e) { return Json(e.loop_closure_note); }},
      {Flat::kKey, "loop_closure_source", Nested::kKey, "loop_closures", "source", with_closures,
       [](const E& e) { return Json(e.loop_closure_source); }},
      both("loop_closures", "loop_closure_csv_rows", with_closures,
           [](const E& e) { return Json(e.loop_closure_csv_rows); }),
      // Only where the csv rows are the scored edges (no graph.json); metrics.json only, so that
      // metrics.csv and a study's columns keep their schema.
      {Flat::kNone, "", Nested::kKey, "loop_closures", "loop_closure_csv_repeated_rows",
       with_closures_from_csv, [](const E& e) { return Json(e.loop_closure_csv_repeated_rows); }},
      {Flat::kKey, "loop_edges_considered", Nested::kKey, "loop_closures", "edges_considered",
       with_closures, [](const E& e) { return Json(e.loop_closure_score.edges_considered); }},
      {Flat::kKey, "loop_edges_short_path", Nested::kKey, "loop_closures", "edges_short_path",
       with_closures, [](const E& e) { return Json(e.loop_closure_score.edges_short_path); }},
      {Flat::kPrefixed, "online_", Nested::kKey, "loop_closures", "online", with_closures,
       [](const E& e) { return e.loop_closure_score.online.to_json(); }},
      {Flat::kPrefixed, "pruned_", Nested::kKey, "loop_closures", "pruned", with_closures,
       [](const E& e) { return e.loop_closure_score.after_pruning.to_json(); }},
      both("loop_closures", "revisit_episodes", with_closures,
           [](const E& e) { return Json(e.revisit_episodes); }),
      both("loop_closures", "revisit_keyframes", with_closures,
           [](const E& e) { return Json(e.revisit_keyframes); }),
      {Flat::kKey, "overlap_used_depth", Nested::kNone, "", "", with_closures,
       [](const E& e) { return Json(e.overlap_used_depth); }},
      both("loop_closures", "overlap_method", with_closures,
           [](const E& e) { return Json(e.overlap_method); }),
      {Flat::kNone, "", Nested::kKey, "loop_closures", "overlap_used_depth", with_closures,
       [](const E& e) { return Json(e.overlap_used_depth); }},
      both("loop_closures", "overlap_pairs_tested", with_closures,
           [](const E& e) { return Json(e.loop_closure_score.pairs_tested); }),
      both("loop_closures", "overlap_pairs_geometric_only", with_closures,
           [](const E& e) { return Json(e.loop_closure_score.pairs_geometric_only); }),
      {Flat::kNone, "", Nested::kKey, "loop_closures", "closures", with_closures, closures_json},
      {Flat::kNone, "", Nested::kKey, "loop_closures", "episodes", with_closures, episodes_json},
      // Time and work.
      {Flat::kKey, "timing_available", Nested::kKey, "timing", "available", always,
       [](const E& e) { return Json(e.timing_available); }},
      {Flat::kNone, "", Nested::kKey, "timing", "note", without_timing,
       [](const E& e) { return Json(e.timing_note); }},
      {Flat::kNone, "", Nested::kMerged, "timing", "", with_timing,
       [](const E& e) { return e.timing.to_json(); }},
      {Flat::kKey, "loop_closure_detection_s", Nested::kNone, "", "", with_timing,
       [](const E& e) { return Json(e.loop_closure_detection_s); }},
      {Flat::kKey, "wifi_overhead_s", Nested::kNone, "", "", with_timing,
       [](const E& e) { return Json(e.wifi_overhead_s); }},
      {Flat::kKey, "optimisation_s", Nested::kNone, "", "", with_timing,
       [](const E& e) { return Json(e.optimisation_s); }},
      {Flat::kKey, "total_s", Nested::kNone, "", "", with_timing,
       [](const E& e) { return Json(e.total_s); }},
      {Flat::kKey, "wall_s", Nested::kNone, "", "", with_timing,
       [](const E& e) { return Json(e.wall_s); }},
      both("timing", "candidate_comparisons", with_timing,
           [](const E& e) { return Json(e.candidate_comparisons); }),
      {Flat::kPrefixed, "counter.", Nested::kNone, "", "", with_timing, counters_json},
      both("timing", "keyframes", always, [](const E& e) { return Json(e.keyframes); }),
      both("", "wifi_clusters", always, [](const E& e) { return Json(e.wifi_clusters); }),
      {Flat::kPrefixed, "threshold.", Nested::kNone, "", "", always,
       [](const E& e) { return e.options.to_json(); }},
  };
  return list;
}

}  // namespace

Json RunEvaluation::flat_metrics() const {
  Json j;
  for (const Metric& m : metric_list()) {
    if (m.flat == Flat::kNone || !m.present(*this)) continue;
    const Json value = m.value(*this);
    if (m.flat == Flat::kKey) {
      j[m.flat_name] = value;
    } else {
      for (const auto& [name, item] : value.items()) j[m.flat_name + name] = item;
    }
  }
  return j;
}

std::vector<std::string> RunEvaluation::flat_metric_names() {
  const RunEvaluation none;
  std::vector<std::string> names;
  for (const Metric& m : metric_list()) {
    if (m.flat == Flat::kKey) {
      names.push_back(m.flat_name);
    } else if (m.flat == Flat::kPrefixed) {
      const Json items = m.value(none);  // kept: items() refers to it
      for (const auto& [name, item] : items.items()) names.push_back(m.flat_name + name);
    }
  }
  return names;
}

Json RunEvaluation::to_ordered_json() const {
  Json j;
  for (const Metric& m : metric_list()) {
    if (m.nested == Nested::kNone || !m.present(*this)) continue;
    Json& section = *m.section ? j[m.section] : j;
    const Json value = m.nested_value ? m.nested_value(*this) : m.value(*this);
    if (m.nested == Nested::kKey) {
      section[m.nested_name] = value;
    } else {
      section.update(value);
    }
  }
  return j;
}

nlohmann::json RunEvaluation::to_json() const {
  return nlohmann::json::parse(to_ordered_json().dump());
}

}  // namespace wifislam::eval
