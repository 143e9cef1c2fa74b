// `wifislam compare <scene.yaml ...> --frontend rgbdslam [--sweep key=v1,v2 ...] [--seeds N]
// -o <dir>`: the paper's vanilla-vs-Wi-Fi experiment on each scene, with the paper-style tables
// printed and written as Markdown, CSV and JSON.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "apps/command_registry.hpp"
#include "apps/option_validators.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "core/stop_signal.hpp"
#include "eval/eval_options.hpp"
#include "sim/scene/scene_loader.hpp"
#include "slam/frontend/front_end_registry.hpp"
#include "slam/slam_options.hpp"
#include "study/comparison_study.hpp"
#include "study/paper/paper_plan.hpp"

namespace wifislam::cli {

namespace {

struct CompareArgs {
  std::vector<std::string> scenes;
  std::string frontend = "rgbdslam";
  std::vector<std::string> sweeps;
  std::vector<std::string> settings;
  std::vector<std::string> eval_settings;
  int seeds = 1;
  double fps = 0.0;
  std::int64_t max_frames = -1;
  int jobs = 1;
  std::string output;
  bool force = false;
  bool no_plots = false;
  bool quiet = false;
  std::string preset;
};

/// `--preset paper-rgbdslam`: the paper's RGBD-SLAM experiment ("RGBD SLAM performance", C Hall)
/// on our c_hall twin: min_matches 50 and 70, 5 seeds, 3 fps (the robot's 30 fps make one run
/// ten times longer; the route, pauses and scans are the same). Options given explicitly win.
/// Returns whether the preset is used (the caller adds the twin to the scenes).
bool apply_preset(CompareArgs& args, const CLI::App& app) {
  if (args.preset.empty()) return false;
  if (args.preset != "paper-rgbdslam") {
    throw ParseError("--preset", args.preset, "unknown preset; known: paper-rgbdslam");
  }
  if (!args.scenes.empty()) {
    throw InvalidInputError("--preset " + args.preset +
                            " runs on the built-in c_hall twin: give no scene file with it (for "
                            "your scenes: --sweep min_matches=50,70 --seeds 5 --fps 3)");
  }
  if (args.sweeps.empty()) args.sweeps.push_back("min_matches=50,70");
  if (app.count("--seeds") == 0) args.seeds = 5;
  if (args.fps <= 0) args.fps = 3.0;
  return true;
}

void run(CompareArgs args, const CLI::App& app) {
  const bool preset = apply_preset(args, app);
  if (!preset && args.scenes.empty()) {
    throw ParseError("compare", "scenes", "give scene files, or --preset paper-rgbdslam");
  }
  study::ComparisonOptions options(args.frontend, args.settings);
  for (const std::string& s : args.sweeps) options.sweeps.push_back(study::parse_sweep(s));
  for (const study::SweepAxis& axis : options.sweeps) {
    if (axis.key == "frontend" && app.count("--frontend") > 0) {
      throw InvalidInputError("--frontend " + args.frontend +
                              ": the front end is also swept (--sweep frontend=...); give it "
                              "once, in the sweep");
    }
  }
  std::vector<std::string> keys, frontends = {options.slam.frontend};
  for (const std::string& s : args.settings) keys.push_back(s.substr(0, s.find('=')));
  for (const study::SweepAxis& axis : options.sweeps) {
    if (axis.key == "frontend")
      frontends = axis.values;
    else
      keys.push_back(axis.key);
  }
  for (const std::string& w : slam::unread_option_warnings(keys, frontends))
    fmt::print(stderr, "compare: warning: {}\n", w);
  // The vocabulary and system files the runs read are inputs as much as the scenes: --force
  // must not replace a folder that holds them.
  OutputFolderRequest output{args.output, args.force, {}, study::comparison_input_files(options)};
  for (const std::string& path : args.scenes) output.inputs.emplace_back(path);
  const bool replace = check_output_folder(output);
  std::vector<sim::scene::Scene> scenes;
  for (const std::string& path : args.scenes) scenes.push_back(sim::scene::load_scene_file(path));
  if (preset) scenes.push_back(study::paper::twin_scene("c_hall"));
  for (const std::string& s : args.eval_settings) eval::set_option(options.eval, s);
  options.seeds = args.seeds;
  if (args.fps > 0) options.fps = args.fps;
  options.max_frames = args.max_frames;
  options.jobs = args.jobs;
  options.plots = !args.no_plots;
  if (!args.quiet) {
    options.on_progress = [](const std::string& line) {
      fmt::print(stderr, "compare: {}\n", line);
    };
  }
  // Ctrl-C or SIGTERM stops the datasets and runs at their next frame and removes the unfinished
  // folder (a folder being replaced stays as it was); declared first, so it goes last.
  const StopOnSignal stop_on_signal;
  AtomicDirectory out(args.output, replace);
  const study::ComparisonResult result =
      study::run_comparison(scenes, options, out.staging_path(), out.final_paths());
  out.commit();
  fmt::print("{}", result.markdown());
  const std::string dir = absolute_folder(args.output).string();
  fmt::print(
      "wrote {0}/comparison.md, comparison.csv, comparison.json; per-run reports and plots "
      "in {0}/runs/<scene>-seed<seed>/<setting>/<variant>/eval/\n",
      dir);
}

}  // namespace

WIFISLAM_COMMAND(compare, 65) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* app = parent.add_subcommand(
      "compare",
      "Run a front end vanilla and with Wi-Fi side by side on one or more scenes, over swept\n"
      "settings and seeds, evaluate every run against exact ground truth, and print the paper's\n"
      "tables (rows: scenes; columns: setting x {Vanilla, WiFi}): trajectory error, false\n"
      "positive %, false negative %, loop-closure time, candidate comparisons, Wi-Fi overhead.");
  // No CLI::ExistingFile: the scene loader says what is wrong with a path, alike in every command.
  app->add_option("scenes", args->scenes, "Scene files (YAML); none with --preset")
      ->check(kNonEmptyInput);
  app->add_option(
      "--preset", args->preset,
      "paper-rgbdslam: the paper's RGBD-SLAM experiment on the built-in c_hall twin\n"
      "(--sweep min_matches=50,70 --seeds 5 --fps 3 unless given; about 26 min on 2 cores)");
  app->add_option(
         "--frontend", args->frontend,
         "Front end (" + slam::frontend::front_end_name_list() +
             "), or external:NAME|FILE, another program (docs/external_systems.md);\n"
             "several side by side: --sweep frontend=rgbdslam,external:opencv_rgbd_odometry")
      ->capture_default_str();
  app->add_option("--sweep", args->sweeps,
                  "Swept SLAM option key=v1,v2,... (repeatable; every combination is run), e.g.\n"
                  "--sweep min_matches=10,15,20,50 --sweep inlier_distance=2,3,5");
  app->add_option("--set", args->settings,
                  "SLAM option key=value for every run (repeatable); keys and defaults: "
                  "wifislam slam --help");
  app->add_option("--eval-set", args->eval_settings,
                  "Evaluation threshold key=value (repeatable; see `wifislam eval --help`)");
  app->add_option("--seeds", args->seeds, "Seeds per scene (scene seed, +1, ...)")
      ->capture_default_str()
      ->check(at_least(1));
  app->add_option("--fps", args->fps, "Dataset frame rate (default: each scene's)")
      ->check(finite_range(0.1, 1000.0));
  app->add_option("--max-frames", args->max_frames, "Cut each dataset after this many frames")
      ->check(at_least(1));
  app->add_option("--jobs", args->jobs,
                  "SLAM runs in parallel, side by side on one rendering of their dataset (results\n"
                  "identical; 1 keeps timings comparable)")
      ->capture_default_str()
      ->check(at_least(1));
  app->add_option("-o,--output", args->output, "Folder to write")->required();
  app->add_flag("--force", args->force,
                "Replace the output folder if it exists and holds this tool's output (never an\n"
                "input, the current directory, the home folder or a folder of your own)");
  app->add_flag("--no-plots", args->no_plots, "Skip the per-run PNG/SVG plots");
  app->add_flag("-q,--quiet", args->quiet, "No progress lines on stderr");
  app->footer(
      "Output: datasets/<scene>-seed<seed>/ (TUM layout), runs/.../{vanilla,wifi}/ (run folders\n"
      "with eval/ reports), comparison.md/.csv/.json. Written as <dir>.partial, renamed at the "
      "end.\n"
      "Timing columns are wall-clock; keep --jobs 1 when comparing them.");
  app->callback([args, app] { run(*args, *app); });
}

}  // namespace wifislam::cli
