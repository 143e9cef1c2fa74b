// `wifislam eval <run-dir> --gt <dataset-dir> [-o out-dir] [--scale] [--no-plots]
// [--set key=value ...]`: score a SLAM run folder against the exact ground truth of its dataset
// and write report.md, metrics.json, metrics.csv and plots.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "apps/command_registry.hpp"
#include "eval/eval.hpp"

namespace {

struct EvalArgs {
  std::string run_dir;
  std::string dataset_dir;
  std::string output;
  bool scale = false;
  bool no_plots = false;
  std::vector<std::string> settings;
};

std::string thresholds_help() {
  const wifislam::eval::EvalOptions defaults;
  const nlohmann::ordered_json values = defaults.to_json();
  std::string text = "Thresholds (--set key=value; all are written into the outputs):\n";
  for (const auto& [name, description] : wifislam::eval::option_descriptions()) {
    text += fmt::format("  {:<30} {:>6}  {}\n", name, values[name].dump(), description);
  }
  return text;
}

void run(const EvalArgs& args) {
  using namespace wifislam;
  eval::EvalOptions options;
  options.align_scale = args.scale;
  for (const std::string& s : args.settings) eval::set_option(options, s);
  const std::filesystem::path out = args.output.empty()
                                        ? std::filesystem::path(args.run_dir) / "eval"
                                        : std::filesystem::path(args.output);
  const eval::RunEvaluation ev = eval::evaluate_run(args.run_dir, args.dataset_dir, options);
  eval::write_evaluation(out, ev, args.run_dir, args.dataset_dir, !args.no_plots);
  fmt::print("ATE RMSE           {:.4f} m (mean {:.4f}, median {:.4f}, max {:.4f}; {} poses)\n",
             ev.ate_rmse_m, ev.ate_mean_m, ev.ate_median_m, ev.ate_max_m, ev.frames_associated);
  fmt::print("RPE                {:.4f} m/m, {:.3f} deg/m over {} m\n", ev.rpe_trans_per_m,
             ev.rpe_rot_deg_per_m, options.rpe_delta_m);
  fmt::print("loop closures      {} detected, {} false positive ({:.1f} %)\n",
             ev.loop_closures_detected, ev.false_positives, ev.false_positive_pct);
  fmt::print("revisit episodes   {}, {} missed ({:.1f} %)\n", ev.revisit_episodes,
             ev.false_negatives, ev.false_negative_pct);
  fmt::print("overlap judged by  {}\n", ev.overlap_method);
  fmt::print(
      "time               loop-closure detection {:.3f} s, Wi-Fi overhead {:.4f} s, "
      "optimisation {:.3f} s, total {:.3f} s\n",
      ev.loop_closure_detection_s, ev.wifi_overhead_s, ev.optimisation_s, ev.total_s);
  fmt::print("wrote {}\n", std::filesystem::absolute(out).lexically_normal().string());
}

}  // namespace

WIFISLAM_COMMAND(eval, 70) {
  auto args = std::make_shared<EvalArgs>();
  CLI::App* app = parent.add_subcommand(
      "eval",
      "Score a SLAM run folder against its dataset's exact ground truth: trajectory error (ATE\n"
      "after Umeyama alignment, RPE per metre), false positive / false negative loop closures,\n"
      "loop-closure time and Wi-Fi overhead. Writes report.md, metrics.json, metrics.csv and\n"
      "PNG/SVG plots (trajectory over the floor plan, error along the path, Wi-Fi clusters).");
  app->add_option("run", args->run_dir, "Run folder written by `wifislam slam`")->required();
  app->add_option("--gt", args->dataset_dir,
                  "Dataset folder the run was made from (groundtruth.txt, depth images, "
                  "calibration.yaml, scene.yaml)")
      ->required();
  app->add_option("-o,--output", args->output,
                  "Folder to write (default: <run>/eval; replaced if it exists)");
  app->add_flag("--scale", args->scale, "Align with scale (Sim(3)) instead of rigidly");
  app->add_flag("--no-plots", args->no_plots, "Write the text outputs only");
  app->add_option("--set", args->settings, "Threshold key=value (repeatable), see below");
  app->footer(thresholds_help());
  app->callback([args] { run(*args); });
}
