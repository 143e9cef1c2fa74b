// `wifislam slam <dataset-dir | scene.yaml> --frontend rgbdslam [--set key=value ...] -o
// <run-dir>`: run visual SLAM on a dataset folder (ours or a plain TUM RGB-D one) or, given a scene
// file, on frames streamed straight from the generator (nothing written but the run folder).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "apps/command_registry.hpp"
#include "apps/option_validators.hpp"
#include "core/output_folder.hpp"
#include "peers/external_run.hpp"
#include "sim/generate/sensor_input.hpp"
#include "slam/frontend/front_end_registry.hpp"
#include "slam/io/run_folder_writer.hpp"
#include "slam/slam_options.hpp"
#include "slam/system/run_slam.hpp"

namespace {

struct SlamArgs {
  std::string input;
  std::string frontend = "rgbdslam";
  bool wifi = false;
  std::vector<std::string> settings;
  std::string output;
  bool force = false;
  bool no_verify = false;
  // Scene input only.
  std::int64_t max_frames = -1;
  double fps = 0.0;
  std::optional<std::uint64_t> scene_seed;
};

/// An external system (--frontend external:X) on a dataset folder, through its system file.
void run_external(const SlamArgs& args, const wifislam::slam::SlamOptions& options, bool replace) {
  using namespace wifislam;
  if (!std::filesystem::is_directory(args.input)) {
    throw InvalidInputError(args.input +
                            ": an external system reads a dataset folder; generate "
                            "one from the scene first (wifislam generate)");
  }
  if (args.max_frames >= 0 || args.fps > 0 || args.scene_seed) {
    throw ParseError("--frontend", options.frontend,
                     "--max-frames, --fps and --seed apply to our front ends; an external system "
                     "reads the whole dataset (its seed is --set seed=N)");
  }
  peers::ExternalRunRequest request =
      peers::external_run_request(options.frontend, options.wifi.enabled, args.input, args.output);
  request.overwrite = replace;
  request.seed = options.seed;
  request.extra_run_info = {{"input", {{"kind", "dataset"}, {"path", args.input}}}};
  const peers::ExternalRunResult result = peers::run_external_system(request);
  const std::string dir = std::filesystem::absolute(args.output).lexically_normal().string();
  if (!result.ok) {
    throw ExternalSystemError(
        fmt::format("{} ({}): {}; its run folder {} has run.json, stdout.log "
                    "and stderr.log",
                    options.frontend, request.system.file.string(), result.status, dir));
  }
  fmt::print("{}: {}, {:.1f} s wall-clock, {:.1f} s CPU\nwrote {}\n", options.frontend,
             result.status, result.process.wall_s, result.process.cpu_s, dir);
}

void run(const SlamArgs& args) {
  using namespace wifislam;
  slam::SlamOptions options;
  options.frontend = args.frontend;
  options.wifi.enabled = args.wifi;
  for (const std::string& s : args.settings) slam::set_option_assignment(options, s);
  slam::validate(options);
  const bool replace = check_output_folder({args.output, args.force, {}, {args.input}});
  if (peers::is_external_frontend(options.frontend)) {
    run_external(args, options, replace);
    return;
  }
  sim::SensorInputOptions input_options;
  input_options.verify_checksums = !args.no_verify;
  input_options.max_frames = args.max_frames;
  if (args.fps > 0) input_options.fps = args.fps;
  input_options.scene_seed = args.scene_seed;
  sim::SensorInput input = sim::open_sensor_input(args.input, input_options);
  SensorStream& stream = *input.stream;
  const bool tty = cli::stderr_is_tty();
  slam::RunSummary summary;
  const auto progress = [tty](std::int64_t frames) {
    if (tty && frames % 30 == 0) fmt::print(stderr, "\rslam: {} frames", frames);
  };
  const std::unique_ptr<slam::SlamSystem> system =
      slam::run_slam(stream, options, summary, progress);
  if (tty) fmt::print(stderr, "\n");
  slam::write_run_folder(args.output, *system, summary, replace, {{"input", input.description}});
  fmt::print("{}", summary.FullReport());
  fmt::print("wrote {}\n", std::filesystem::absolute(args.output).lexically_normal().string());
}

}  // namespace

WIFISLAM_COMMAND(slam, 60) {
  auto args = std::make_shared<SlamArgs>();
  CLI::App* app = parent.add_subcommand(
      "slam",
      "Run visual SLAM on a dataset folder (ours or plain TUM RGB-D) or on frames streamed from\n"
      "a scene file, and write the run folder (trajectory.txt, keyframes.txt, graph.json,\n"
      "loop_closures.csv, timing.json with per-role comparison counters, run.json, and\n"
      "wifi_clusters.csv with --wifi; layout in core/run_format.hpp).");
  app->add_option("input", args->input, "Dataset folder or scene file (YAML)")->required();
  app->add_option("--frontend", args->frontend,
                  "SLAM front end: memory, loop-closure candidates and acceptance (" +
                      wifislam::slam::front_end_name_list() +
                      "), or external:NAME|FILE, another program run from its system file\n"
                      "on a dataset folder (shipped: " +
                      fmt::format("{}", fmt::join(wifislam::peers::shipped_system_names(), ", ")) +
                      "; docs/external_systems.md)")
      ->capture_default_str();
  app->add_flag(
      "--wifi", args->wifi,
      "Give the front end the Wi-Fi module (works with every --frontend): cluster keyframes by\n"
      "Wi-Fi signature and bound the loop-closure search to similar clusters (needs wifi.csv /\n"
      "scans in the scene)");
  app->add_option("--set", args->settings,
                  "SLAM option key=value (repeatable), e.g. --set min_matches=15 "
                  "--set inlier_distance=2.0; every key is listed below");
  app->add_option("-o,--output", args->output, "Run folder to write")->required();
  app->add_flag("--force", args->force,
                "Replace an existing run folder (never an input, the current directory, the\n"
                "home folder or a folder that is not this tool's output)");
  app->add_flag("--no-verify", args->no_verify, "Do not check the dataset's SHA-256 sums");
  app->add_option("--max-frames", args->max_frames,
                  "Stop after this many frames (scene or dataset input)")
      ->check(CLI::PositiveNumber);
  app->add_option("--fps", args->fps, "Scene input only: frame rate (default: the scene's)")
      ->check(wifislam::cli::finite_range(0.1, 1000.0));
  app->add_option("--seed", args->scene_seed, "Scene input only: replace the scene's seed")
      ->check(wifislam::cli::kSeedValidator);
  // RTAB-Map's and ORB-SLAM2's parameters keep their defaults and are named after them here.
  app->footer("SLAM options (--set key=value; shown with their defaults):\n" +
              wifislam::slam::option_reference());
  app->callback([args] { run(*args); });
}
