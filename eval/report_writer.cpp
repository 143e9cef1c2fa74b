#include "eval/report_writer.hpp"

#include <optional>
#include <utility>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/csv_field.hpp"
#include "core/error.hpp"
#include "eval/plots.hpp"

namespace wifislam::eval {

namespace fs = std::filesystem;

const char* const kAssociationRule =
    "Association (TUM associate.py, ground truth first, estimate second): stamps increase "
    "strictly in each file (a repeated stamp is refused at its line, where associate.py would "
    "keep the last one silently); every pair closer than max_time_difference_s "
    "(strictly) is a candidate; candidates are taken greedily by smallest |difference|, exact "
    "ties going to the earlier ground-truth stamp, then the earlier estimate stamp, each stamp "
    "used once. Differences are exact in integer nanoseconds (associate.py subtracts "
    "floating-point seconds).";

namespace {

std::string csv_field(const nlohmann::ordered_json& v) {
  if (v.is_string()) return wifislam::csv_field(v.get<std::string>());
  if (v.is_number_float()) return wifislam::csv_field(fmt::format("{}", v.get<double>()));
  return wifislam::csv_field(v.dump());
}

std::string alignment_name(AlignmentMode mode) {
  switch (mode) {
    case AlignmentMode::kNone:
      return "no alignment";
    case AlignmentMode::kSe3:
      return "Umeyama rigid, SE(3)";
    case AlignmentMode::kSim3:
      return "Umeyama with scale, Sim(3)";
  }
  return "";
}

std::string value_text(const nlohmann::ordered_json& v) {
  if (v.is_number_float()) return fmt::format("{}", v.get<double>());
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

/// report.md, built section by section.
class Markdown {
 public:
  void line(const std::string& s = "") { text_ += s + "\n"; }
  std::string text() && { return std::move(text_); }

 private:
  std::string text_;
};

void summary_section(Markdown& md, const RunEvaluation& ev) {
  const auto line = [&md](const std::string& s = "") { md.line(s); };
  const LoopClosureCounts& online = ev.loop_closure_score.online;
  const LoopClosureCounts& pruned = ev.loop_closure_score.after_pruning;
  line("## Summary");
  line();
  line("| metric | value |");
  line("| --- | --- |");
  line(fmt::format("| trajectory error (ATE RMSE, {}) | {:.4f} m |",
                   alignment_name(ev.options.align), ev.ate_rmse_m));
  if (ev.loop_closures_available) {
    line(fmt::format(
        "| false positive loop closures (wrong place), online / after pruning | {} of {} ({:.1f} "
        "%) / {} of {} ({:.1f} %) |",
        online.wrong_place, online.scored, online.false_positive_pct, pruned.wrong_place,
        pruned.scored, pruned.false_positive_pct));
    line(fmt::format(
        "| false negatives (missed revisit episodes), online / after pruning | {} of {} ({:.1f} "
        "%) / {} of {} ({:.1f} %) |",
        online.false_negatives, ev.revisit_episodes, online.false_negative_pct,
        pruned.false_negatives, ev.revisit_episodes, pruned.false_negative_pct));
  } else {
    line(fmt::format("| loop closures | {} |", ev.loop_closure_note));
  }
  if (ev.timing_available) {
    line(fmt::format("| loop-closure detection time | {:.3f} s |", ev.loop_closure_detection_s));
    line(fmt::format("| Wi-Fi overhead (clustering + cluster management) | {:.4f} s |",
                     ev.wifi_overhead_s));
    line(fmt::format("| optimisation time | {:.3f} s |", ev.optimisation_s));
    line(fmt::format("| pipeline total / wall-clock | {:.3f} s / {:.3f} s |", ev.total_s,
                     ev.wall_s));
    line(fmt::format("| keyframes / candidate comparisons | {} / {} |", ev.keyframes,
                     ev.candidate_comparisons));
  } else {
    line(fmt::format("| timing | {} |", ev.timing_note));
  }
  if (ev.wifi_run) line(fmt::format("| Wi-Fi clusters | {} |", ev.wifi_clusters));
  line();
}

void trajectory_section(Markdown& md, const RunEvaluation& ev) {
  const auto line = [&md](const std::string& s = "") { md.line(s); };
  line("## Trajectory error");
  line();
  line(fmt::format(
      "{} estimated poses, {} ground-truth poses, {} associated{}. {}", ev.frames_estimated,
      ev.frames_ground_truth, ev.frames_associated,
      ev.options.time_offset_s != 0.0
          ? fmt::format(" (estimate stamps shifted by {} s first)", ev.options.time_offset_s)
          : "",
      kAssociationRule));
  line(fmt::format("Estimate aligned onto ground truth: {}{}.", alignment_name(ev.options.align),
                   ev.options.align == AlignmentMode::kSim3
                       ? fmt::format(", scale {:.5f}", ev.alignment.scale)
                       : ""));
  line();
  line("| ATE | RMSE | mean | median | max |");
  line("| --- | --- | --- | --- | --- |");
  line(fmt::format("| metres | {:.4f} | {:.4f} | {:.4f} | {:.4f} |", ev.ate_rmse_m, ev.ate_mean_m,
                   ev.ate_median_m, ev.ate_max_m));
  line();
  if (ev.rpe_pairs == 0) {
    line(
        fmt::format("RPE over {} m of ground-truth travel: not measured, no two poses are that "
                    "far apart along the path (lower rpe_delta_m).",
                    ev.options.rpe_delta_m));
  } else {
    line(fmt::format(
        "RPE over {} m of ground-truth travel ({} pairs): {:.4f} m/m translation, {:.3f} deg/m "
        "rotation (mean error / segment length); RMSE {:.4f} m, {:.3f} deg.",
        ev.options.rpe_delta_m, ev.rpe_pairs, ev.rpe_trans_per_m, ev.rpe_rot_deg_per_m,
        ev.rpe_trans_rmse_m, ev.rpe_rot_rmse_deg));
  }
  line();
}

void closures_table(Markdown& md, const LoopClosureScore& score) {
  const auto line = [&md](const std::string& s = "") { md.line(s); };
  if (!score.closures.empty()) {
    line();
    line(
        "| from kf | to kf | type | role | inliers | pruned | true distance m | path between m "
        "| trans err m | rot err deg | overlap | verdict |");
    line("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |");
    for (const ScoredLoopClosure& c : score.closures) {
      const AcceptedEdge& e = c.edge;
      line(fmt::format(
          "| {} | {} | {} | {} | {} | {} | {:.2f} | {:.1f} | {:.3f} | {:.2f} | {} | {}{} |",
          e.from_keyframe, e.to_keyframe, e.type, e.role.empty() ? "-" : e.role, e.inliers,
          e.pruned ? "yes" : "no", c.true_distance_m, c.path_between_m, c.translation_error_m,
          c.rotation_error_deg,
          c.overlap.depth_checked ? fmt::format("{:.2f}", c.overlap.fraction)
                                  : std::string(c.overlap.overlap ? "bound" : "no"),
          to_string(c.verdict), c.far ? " (far)" : ""));
    }
  }
}

void episodes_table(Markdown& md, const LoopClosureScore& score) {
  const auto line = [&md](const std::string& s = "") { md.line(s); };
  if (!score.episodes.empty()) {
    line();
    line(
        "| episode | keyframes | revisiting | partner of first | travel between m | detected "
        "online | detected after pruning |");
    line("| --- | --- | --- | --- | --- | --- | --- |");
    for (std::size_t i = 0; i < score.episodes.size(); ++i) {
      const RevisitEpisode& e = score.episodes[i];
      line(fmt::format("| {} | {}-{} | {} | {} | {:.1f} | {} | {} |", i, e.first_keyframe,
                       e.last_keyframe, e.revisiting_keyframes, e.first_partner,
                       e.first_partner_path_m, e.detected_online ? "yes" : "**no (FN)**",
                       e.detected_after_pruning ? "yes" : "**no (FN)**"));
    }
  }
}

void loop_closure_section(Markdown& md, const RunEvaluation& ev) {
  const auto line = [&md](const std::string& s = "") { md.line(s); };
  const LoopClosureScore& score = ev.loop_closure_score;
  const LoopClosureCounts& online = score.online;
  const LoopClosureCounts& pruned = score.after_pruning;
  line("## Loop closures");
  line();
  const EvalOptions& o = ev.options;
  if (!ev.loop_closures_available) {
    line(fmt::format("Loop closures {}; only the trajectory was scored.", ev.loop_closure_note));
    line();
  } else {
    line(fmt::format(
        "Scored edges (from {}): every accepted `visual` or `loop` edge whose keyframes lie at "
        "least {} m of ground-truth path apart, whatever the front end called it ({} such edges "
        "of {} visual/loop edges; {} shorter ones are tracking or local edges, not scored; "
        "loop_closures.csv has {} rows{}).",
        ev.loop_closure_source, o.revisit_min_path_m, online.scored, score.edges_considered,
        score.edges_short_path, ev.loop_closure_csv_rows,
        ev.loop_closure_csv_repeated_rows == 0
            ? std::string()
            : fmt::format(", of which {} repeat the keyframe pair of an earlier row and are "
                          "scored once, as that row",
                          ev.loop_closure_csv_repeated_rows)));
    line(fmt::format(
        "Verdict from the relative pose and the true positions only: **correct** when the "
        "estimated relative pose is within {} m and {} deg of the ground truth inv(gt_from) * "
        "gt_to; **right place, imprecise** when not, but the keyframes truly stand within {} m of "
        "each other and the error is within {} m and {} deg; **wrong place** otherwise (the "
        "paper's false positive; **far** when the keyframes truly stand more than {} m apart). "
        "FP % = wrong place / scored edges. Online = every scored edge as accepted during the "
        "run; after pruning = those the after-run pruning kept.",
        o.loop_max_translation_error_m, o.loop_max_rotation_error_deg, o.right_place_max_distance_m,
        o.right_place_max_translation_error_m, o.right_place_max_rotation_error_deg,
        o.far_distance_m));
    line();
    line(
        "| set | scored | correct | right place, imprecise | wrong place | far wrong place | FP % "
        "| missed episodes (FN) | FN % |");
    line("| --- | --- | --- | --- | --- | --- | --- | --- | --- |");
    for (const auto& [name, c] :
         {std::pair{"online", &online}, std::pair{"after pruning", &pruned}}) {
      line(fmt::format("| {} | {} | {} | {} | {} | {} | {:.1f} | {} of {} | {:.1f} |", name,
                       c->scored, c->correct, c->right_place_imprecise, c->wrong_place,
                       c->far_wrong_place, c->false_positive_pct, c->false_negatives,
                       ev.revisit_episodes, c->false_negative_pct));
    }
    line();
    line(fmt::format(
        "False negatives: views overlap when the ground-truth cameras are at most {} m apart with "
        "optical axes within {} deg, and (with depth) at least {:.0f} % of one view's depth "
        "samples (every {} px) land in the other view with its depth agreeing within max({} m, "
        "{:.0f} %) (lookup grid {} px). Overlap judged by: **{}**. A true revisit is a pair of "
        "overlapping keyframes with at least {} m of ground-truth travel between them; an "
        "episode is a run of revisiting keyframes (gaps of up to {} keyframes allowed), detected "
        "when a correct edge of the set touches it. {} revisit episodes ({} revisiting "
        "keyframes).",
        o.overlap_max_distance_m, o.overlap_max_angle_deg, 100 * o.overlap_min_fraction,
        o.overlap_sample_stride_px, o.overlap_depth_tolerance_m,
        100 * o.overlap_depth_tolerance_rel, o.overlap_lookup_stride_px, ev.overlap_method,
        o.revisit_min_path_m, o.episode_max_gap_keyframes, ev.revisit_episodes,
        ev.revisit_keyframes));
    closures_table(md, score);
    episodes_table(md, score);
    line();
  }
}

void time_section(Markdown& md, const RunEvaluation& ev) {
  const auto line = [&md](const std::string& s = "") { md.line(s); };
  line("## Time");
  line();
  if (!ev.timing_available) {
    line(fmt::format("Timing {}.", ev.timing_note));
    line();
  } else {
    line("Wall-clock of the run per module (timing.json) and work counters (machine-independent).");
    line();
    line("| module | seconds | calls |");
    line("| --- | --- | --- |");
    for (const auto& [name, m] : ev.timing.modules) {
      line(fmt::format("| {} | {:.4f} | {} |", name, m.total_s, m.calls));
    }
    line();
    line("| counter | value |");
    line("| --- | --- |");
    for (const auto& [name, v] : ev.timing.counters) line(fmt::format("| {} | {} |", name, v));
    if (!ev.timing.roles.empty()) {
      line();
      line(
          "Visual comparisons by the role that asked for them (verified: the transformation "
          "passed; accepted: it became an edge, or for tracking, the frame was tracked).");
      line();
      line("| role | comparisons | RANSAC runs | verified | accepted | seconds |");
      line("| --- | --- | --- | --- | --- | --- |");
      for (const auto& [name, r] : ev.timing.roles) {
        line(fmt::format("| {} | {} | {} | {} | {} | {:.4f} |", name, r.comparisons, r.ransac_runs,
                         r.verified, r.accepted, r.time_s));
      }
    }
    line();
  }
}

void thresholds_and_notes(Markdown& md, const RunEvaluation& ev,
                          const std::vector<std::string>& notes) {
  const auto line = [&md](const std::string& s = "") { md.line(s); };
  line("## Thresholds");
  line();
  line("| threshold | value | meaning |");
  line("| --- | --- | --- |");
  const nlohmann::ordered_json thresholds = ev.options.to_json();
  for (const auto& [name, description] : option_descriptions()) {
    line(fmt::format("| `{}` | {} | {} |", name, value_text(thresholds[name]), description));
  }
  if (!notes.empty()) {
    line();
    line("## Notes");
    line();
    for (const std::string& n : notes) line("- " + n);
  }
}

}  // namespace

std::string render_report_markdown(const RunEvaluation& ev, const std::vector<std::string>& notes) {
  Markdown md;
  const auto line = [&md](const std::string& s = "") { md.line(s); };
  line("# SLAM run evaluation");
  line();
  line(fmt::format("- run: `{}`{}", ev.run_dir,
                   ev.frontend.empty() ? ""
                                       : fmt::format(" (front end `{}`{})", ev.frontend,
                                                     ev.wifi_run ? ", with Wi-Fi" : "")));
  line(fmt::format("- ground truth: `{}`", ev.dataset_dir));
  line();
  summary_section(md, ev);
  trajectory_section(md, ev);
  loop_closure_section(md, ev);
  time_section(md, ev);
  thresholds_and_notes(md, ev, notes);
  return std::move(md).text();
}

std::string render_metrics_csv(const RunEvaluation& ev) {
  const nlohmann::ordered_json flat = ev.flat_metrics();
  std::string header, row;
  bool first = true;
  for (const auto& [key, value] : flat.items()) {
    header += (first ? "" : ",") + key;
    row += (first ? "" : ",") + csv_field(value);
    first = false;
  }
  return header + "\n" + row + "\n";
}

void write_evaluation(const fs::path& out_dir, const RunEvaluation& ev, bool plots,
                      const PlanBackdrop& backdrop) {
  std::vector<std::string> notes;
  if (plots && !backdrop.plan) {
    notes.push_back("plots drawn without floor plan: " + backdrop.missing_reason);
  }
  AtomicDirectory out(out_dir, /*overwrite=*/true);
  const fs::path& dir = out.staging_path();
  if (plots) {
    for (const char* ext : {".png", ".svg"}) {
      plot_trajectory(dir / (std::string("trajectory") + ext), ev, backdrop.plan);
      plot_error_along_path(dir / (std::string("ate_along_path") + ext), ev);
      if (ev.wifi_run) {
        plot_wifi_clusters(dir / (std::string("wifi_clusters") + ext), ev, backdrop.plan);
      }
    }
  }
  write_file_atomic(dir / "report.md", render_report_markdown(ev, notes));
  write_file_atomic(dir / "metrics.json", ev.to_ordered_json().dump(1) + "\n");
  write_file_atomic(dir / "metrics.csv", render_metrics_csv(ev));
  out.commit();
}

}  // namespace wifislam::eval
