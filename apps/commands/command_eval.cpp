// `wifislam eval <run-dir | trajectory.txt> --gt <dataset-dir> [-o out-dir] [--align MODE]
// [--time-offset S] [--no-plots] [--set key=value ...]`: score a SLAM run folder, or any TUM
// trajectory file, against the exact ground truth of a dataset and write report.md,
// metrics.json, metrics.csv and plots.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "apps/command_registry.hpp"
#include "apps/option_validators.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "core/text_lines.hpp"
#include "eval/eval.hpp"
#include "eval/requirement.hpp"
#include "sim/world/world_generator.hpp"

namespace wifislam::cli {

namespace {

struct EvalArgs {
  std::string input;
  std::string dataset_dir;
  std::string output;
  std::optional<std::string> align;  // as given: "" is refused, not the default
  std::optional<double> time_offset_s;
  bool scale = false;
  bool no_plots = false;
  bool force = false;
  bool no_verify = false;
  std::vector<std::string> settings;
  std::vector<std::string> requirements;
};

std::string thresholds_help() {
  const eval::EvalOptions defaults;
  const nlohmann::ordered_json values = defaults.to_json();
  std::string text = "Thresholds (--set key=value; all are written into the outputs):\n";
  for (const auto& [name, description] : eval::option_descriptions()) {
    text += fmt::format("  {:<36} {:>6}  {}\n", name, values[name].dump(), description);
  }
  text += "\n";
  text += eval::kAssociationRule;
  text += "\n";
  return text;
}

/// A trajectory given as a pipe (`<(...)` in a shell): read as a file is, but with no folder
/// to write the evaluation beside.
bool is_pipe(const std::filesystem::path& input) {
  std::error_code ec;
  return std::filesystem::is_fifo(std::filesystem::status(input, ec));
}

/// Default output: <run>/eval for a folder, <name>_eval beside a trajectory file.
std::filesystem::path default_output(const std::filesystem::path& input) {
  if (std::filesystem::is_regular_file(input)) {
    return input.parent_path() / (input.stem().string() + "_eval");
  }
  return input / "eval";
}

void run(const EvalArgs& args) {
  eval::EvalOptions options;
  if (args.scale) options.align = eval::AlignmentMode::kSim3;  // deprecated spelling
  if (args.align) {
    const std::optional<eval::AlignmentMode> mode = eval::parse_alignment_mode(*args.align);
    if (!mode) {
      throw InvalidInputError("--align '" + *args.align + "': expected none, se3 or sim3");
    }
    if (args.scale && *mode != eval::AlignmentMode::kSim3) {
      throw InvalidInputError("--scale (= --align sim3) contradicts --align " + *args.align);
    }
    options.align = *mode;
  }
  if (args.time_offset_s) options.time_offset_s = *args.time_offset_s;
  for (const std::string& s : args.settings) {
    // One place for the offset and the alignment: a --set after the flag won silently, in
    // either order.
    if (args.time_offset_s && s.rfind("time_offset_s=", 0) == 0) {
      throw InvalidInputError("--set " + s + ": conflicts with --time-offset " +
                              format_double_exact(*args.time_offset_s) + "; give one of them");
    }
    if ((args.align || args.scale) && s.rfind("align=", 0) == 0) {
      throw InvalidInputError("--set " + s + ": conflicts with " +
                              (args.align ? "--align " + *args.align : std::string("--scale")) +
                              "; give one of them");
    }
    eval::set_option(options, s);
  }
  if (args.output.empty() && is_pipe(args.input)) {
    throw InvalidInputError(args.input +
                            ": a trajectory read from a pipe has no folder to write the "
                            "evaluation beside; give the output folder (-o)");
  }
  const std::filesystem::path default_out = default_output(args.input);
  const std::filesystem::path out =
      args.output.empty() ? default_out : std::filesystem::path(args.output);
  // Malformed requirements and unknown metrics are bad input before anything is written.
  std::vector<eval::Requirement> requirements;
  for (const std::string& text : args.requirements)
    requirements.push_back(eval::parse_requirement(text));
  // The default may lie inside the run folder it evaluates (<run>/eval), never inside the
  // ground truth's dataset (a trajectory file's <file>_eval beside it there).
  const std::filesystem::path run_folder =
      std::filesystem::is_regular_file(args.input) || is_pipe(args.input)
          ? std::filesystem::path()
          : std::filesystem::path(args.input);
  check_output_folder({out, args.force, default_out, {args.input, args.dataset_dir}, run_folder});
  const eval::RunEvaluation ev =
      eval::evaluate_run(args.input, args.dataset_dir, options, !args.no_verify);
  const nlohmann::ordered_json flat = ev.flat_metrics();
  eval::check_metric_names(requirements, flat);
  eval::PlanBackdrop backdrop;
  std::optional<sim::world::World> world;
  if (!args.no_plots) {
    world = sim::world::dataset_world(args.dataset_dir, backdrop.missing_reason);
    if (world) backdrop.plan = &world->plan;
  }
  eval::write_evaluation(out, ev, !args.no_plots, backdrop);
  fmt::print("ATE RMSE           {:.4f} m (mean {:.4f}, median {:.4f}, max {:.4f}; {} poses, {})\n",
             ev.ate_rmse_m, ev.ate_mean_m, ev.ate_median_m, ev.ate_max_m, ev.frames_associated,
             eval::to_string(options.align));
  if (ev.rpe_pairs == 0) {
    fmt::print("RPE                not measured: no two poses {} m apart along the path\n",
               options.rpe_delta_m);
  } else {
    fmt::print("RPE                {:.4f} m/m, {:.3f} deg/m over {} m\n", ev.rpe_trans_per_m,
               ev.rpe_rot_deg_per_m, options.rpe_delta_m);
  }
  if (ev.loop_closures_available) {
    for (const auto& [name, c] :
         {std::pair{"online", &ev.loop_closure_score.online},
          std::pair{"after pruning", &ev.loop_closure_score.after_pruning}}) {
      fmt::print(
          "loop closures      {:<14} {} scored: {} correct, {} right place imprecise, {} wrong "
          "place ({:.1f} %, {} far); {} of {} episodes missed ({:.1f} %)\n",
          name, c->scored, c->correct, c->right_place_imprecise, c->wrong_place,
          c->false_positive_pct, c->far_wrong_place, c->false_negatives, ev.revisit_episodes,
          c->false_negative_pct);
    }
    fmt::print("overlap judged by  {}\n", ev.overlap_method);
  } else {
    fmt::print("loop closures      {}\n", ev.loop_closure_note);
  }
  if (ev.timing_available) {
    fmt::print(
        "time               loop-closure detection {:.3f} s, Wi-Fi overhead {:.4f} s, "
        "optimisation {:.3f} s, total {:.3f} s\n",
        ev.loop_closure_detection_s, ev.wifi_overhead_s, ev.optimisation_s, ev.total_s);
  } else {
    fmt::print("time               {}\n", ev.timing_note);
  }
  fmt::print("wrote {}\n", absolute_folder(out).string());
  int failed = 0;
  for (const eval::RequirementResult& r : eval::check_requirements(requirements, flat)) {
    fmt::print("requirement        {}\n", r.describe());
    failed += !r.met;
  }
  if (failed > 0) {
    throw RequirementNotMetError(
        fmt::format("{} of {} requirements not met (exit 6)", failed, requirements.size()));
  }
}

}  // namespace

WIFISLAM_COMMAND(eval, 70) {
  auto args = std::make_shared<EvalArgs>();
  CLI::App* app = parent.add_subcommand(
      "eval",
      "Score a SLAM run folder, or any TUM trajectory file (e.g. another system's\n"
      "CameraTrajectory.txt), against a dataset's exact ground truth: trajectory error (ATE after\n"
      "alignment, RPE per metre) and, for run folders with keyframes.txt and graph.json or\n"
      "loop_closures.csv, loop closures (correct / right place imprecise / wrong place, online\n"
      "and after pruning; missed revisits); with timing.json, loop-closure time and Wi-Fi\n"
      "overhead. What the input lacks is reported as not available. Writes report.md,\n"
      "metrics.json, metrics.csv and PNG/SVG plots (trajectory over the floor plan, error along\n"
      "the path, Wi-Fi clusters).");
  app->add_option("run", args->input,
                  "Run folder written by `wifislam slam` (only trajectory.txt is required), or a "
                  "TUM trajectory file")
      ->required()
      ->check(kNonEmptyInput);
  app->add_option("--gt", args->dataset_dir,
                  "Dataset folder the run was made from (groundtruth.txt, depth images, "
                  "calibration.yaml, scene.yaml)")
      ->required()
      ->check(kNonEmptyInput);
  app->add_option("-o,--output", args->output,
                  "Folder to write (default: <run>/eval, or <file>_eval beside a trajectory "
                  "file, which is replaced if it exists; any other existing folder only with "
                  "--force)");
  app->add_flag("--force", args->force,
                "Replace an existing output folder that is not the default (only this tool's "
                "output, never an input, the current directory or the home folder)");
  app->add_option("--align", args->align,
                  "Move the estimate onto ground truth before ATE: none, se3 (rigid Umeyama, "
                  "default, as evaluate_ate.py) or sim3 (with scale, evo -as)");
  app->add_option("--time-offset", args->time_offset_s,
                  "Seconds added to the estimate's stamps before association (evaluate_ate.py "
                  "--offset)");
  app->add_flag("--scale", args->scale, "Deprecated: same as --align sim3");
  app->add_flag("--no-plots", args->no_plots, "Write the text outputs only");
  app->add_flag("--no-verify", args->no_verify,
                "Do not check the ground truth against the dataset's manifest.json");
  app->add_option("--set", args->settings, "Threshold key=value (repeatable), see below");
  app->add_option("--require", args->requirements,
                  "METRIC OP NUMBER (repeatable), e.g. 'ate_rmse_m<=0.5' or\n"
                  "'online_wrong_place==0': METRIC a column of metrics.csv, OP one of\n"
                  "<= < >= > == !=. Exit 6 when one is not met (a metric the run does not\n"
                  "have is not met), after writing the outputs; exit 2 for a malformed one");
  app->footer(thresholds_help());
  app->callback([args] { run(*args); });
}

}  // namespace wifislam::cli
