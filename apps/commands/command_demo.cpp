// `wifislam demo`: the main job, small and quick. The paper's experiment in miniature on the
// embedded twin-corridor scene (or a given one): generate a dataset, run RGBD-SLAM vanilla and
// with Wi-Fi, score both against exact ground truth, print the comparison table, and leave the
// plots (trajectories over the floor plan, Wi-Fi clusters, error along the path) and the floor
// plan / radio map pictures in one output folder.
#include <filesystem>

#include <fmt/core.h>

#include "apps/command_registry.hpp"
#include "apps/demo_scene.hpp"
#include "apps/option_validators.hpp"
#include "core/atomic_file.hpp"
#include "core/output_folder.hpp"
#include "core/stop_signal.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/site/site_pictures.hpp"
#include "study/comparison_study.hpp"

namespace wifislam::cli {

namespace {

/// The demo's own folder: replaced on every run without --force (scripts/demo.sh runs it twice).
constexpr const char* kDefaultOutput = "demo-output";

struct DemoArgs {
  std::string output_dir = kDefaultOutput;
  std::string scene_path;
  bool force = false;
  bool quiet = false;
};

/// The plan and radio map of the site the comparison generated its dataset from.
void draw_scene_pictures(const sim::site::Site& site, const std::filesystem::path& dir) {
  sim::site::draw_site_plan(site, dir / "plan.png");
  // Strongest-AP radio map at 0.25 m: what the robot's Wi-Fi card hears on average, at the height
  // and with the shadowing of the dataset's scans.
  radio_model::RadioMapOptions map_options;
  map_options.receiver_height_m = site.receiver_height_m();
  sim::site::draw_site_radio_map(site, map_options, dir / "radio_map.png");
  write_file_atomic(dir / "scene.yaml", sim::scene::resolved_scene_yaml(site.scene()));
}

void run_demo(const DemoArgs& args) {
  const bool replace =
      check_output_folder({args.output_dir, args.force, kDefaultOutput, {args.scene_path}});
  const sim::scene::Scene scene =
      args.scene_path.empty()
          ? sim::scene::load_scene_yaml(cli::kDemoSceneYaml, "<embedded demo scene>")
          : sim::scene::load_scene_file(args.scene_path);
  // Ctrl-C or SIGTERM stops the datasets and runs at their next frame and removes the unfinished
  // folder (a folder being replaced stays as it was); declared first, so it goes last.
  const StopOnSignal stop_on_signal;
  AtomicDirectory out(args.output_dir, replace);

  // rgbdslam, one seed, min_matches 10: the low end of the paper's sweep, where vanilla RGBD-SLAM
  // is likeliest to accept false loop closures between look-alike places (apps/demo_scene.hpp
  // gives what it measures); the c_hall twin (`wifislam compare --preset paper-rgbdslam`) shows
  // the effect in full.
  study::ComparisonOptions options("rgbdslam", {"min_matches=10"});
  if (!args.quiet) {
    options.on_progress = [](const std::string& line) { fmt::print(stderr, "demo: {}\n", line); };
  }
  const study::ComparisonResult result =
      study::run_comparison({scene}, options, out.staging_path(), out.final_paths());
  draw_scene_pictures(*result.sites.front(), out.staging_path());
  out.commit();

  const std::string dir = absolute_folder(args.output_dir).string();
  fmt::print("scene: {} (RGBD-SLAM vanilla vs with Wi-Fi, min_matches 10)\n\n{}\n", scene.name,
             result.markdown());
  fmt::print("wrote {}/\n", dir);
  fmt::print(
      "  plan.png, radio_map.png      the floor plan (walls, APs, route) and strongest-AP map\n");
  fmt::print("  comparison.md/.csv/.json     the tables above, and every metric per run\n");
  for (const study::ComparisonCase& c : result.cases) {
    const std::string eval_dir = (c.run_dir / "eval").string();
    fmt::print(
        "  {}/  {} run: trajectory.png (estimate vs ground truth, loop closures true/false), "
        "ate_along_path.png{}, report.md\n",
        eval_dir, c.wifi ? "Wi-Fi" : "vanilla", c.wifi ? ", wifi_clusters.png" : "");
  }
}

}  // namespace

WIFISLAM_COMMAND(demo, 10) {
  auto args = std::make_shared<DemoArgs>();
  CLI::App* app = parent.add_subcommand(
      "demo",
      "The paper's experiment in miniature (about 1.5 min on 2 cores): on a small embedded\n"
      "scene with two look-alike corridors, generate an RGB-D + Wi-Fi dataset, run RGBD-SLAM\n"
      "(min_matches 10) vanilla and with Wi-Fi, score both against exact ground truth and print\n"
      "the comparison\n"
      "(trajectory error, false/missed loop closures, loop-closure time, Wi-Fi overhead).\n"
      "Everything, plots included, goes into the output folder; ./demo-output, the default,\n"
      "is replaced on every run, any other existing folder only with --force.\n"
      "For bigger studies use `wifislam compare`.");
  app->add_option("-o,--output", args->output_dir, "Output folder")->capture_default_str();
  app->add_flag("--force", args->force,
                "Replace an existing output folder other than the default (only this tool's "
                "output)");
  // No CLI::ExistingFile: the scene loader says what is wrong with a path, alike in every command.
  app->add_option("--scene", args->scene_path, "Use this scene file instead of the embedded one")
      ->check(kNonEmptyInput);
  app->add_flag("-q,--quiet", args->quiet, "No progress lines on stderr");
  app->callback([args] { run_demo(*args); });
}

}  // namespace wifislam::cli
