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
#include "core/stop_signal.hpp"
#include "interop/external_run.hpp"
#include "interop/external_system.hpp"
#include "slam/frontend/front_end_registry.hpp"
#include "slam/slam_options.hpp"
#include "study/slam_run.hpp"

namespace wifislam::cli {

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

void run(const SlamArgs& args) {
  study::SlamRunRequest request;
  request.input = args.input;
  request.output = args.output;
  request.options.frontend = args.frontend;
  request.options.wifi.enabled = args.wifi;
  std::vector<std::string> keys;
  for (const std::string& s : args.settings) {
    slam::set_option_assignment(request.options, s);
    keys.push_back(s.substr(0, s.find('=')));
  }
  for (const std::string& w : slam::unread_option_warnings(keys, {request.options.frontend}))
    fmt::print(stderr, "slam: warning: {}\n", w);
  request.force = args.force;
  request.verify_checksums = !args.no_verify;
  request.max_frames = args.max_frames;
  if (args.fps > 0) request.fps = args.fps;
  request.scene_seed = args.scene_seed;
  const bool tty = cli::stderr_is_tty();
  request.on_frame = [tty](std::int64_t frames) {
    if (tty && frames % 30 == 0) fmt::print(stderr, "\rslam: {} frames", frames);
  };
  // An external system's run folder is written while it runs: Ctrl-C or SIGTERM stops the
  // system and removes that unfinished folder (a folder being replaced stays as it was). Our
  // own front ends write theirs only after the run, so there the signals keep ending the process
  // at once (building a scene's world before the first frame takes seconds, unchecked).
  std::optional<StopOnSignal> stop_on_signal;
  if (interop::is_external_frontend(request.options.frontend)) stop_on_signal.emplace();
  const study::SlamRunResult result = study::run_slam_to_folder(request);
  if (result.external) {
    const interop::ExternalRunResult& external = *result.external;
    fmt::print("{}: {}, {:.1f} s wall-clock, {:.1f} s CPU\n", request.options.frontend,
               external.status, external.process.wall_s, external.process.cpu_s);
  } else {
    if (tty) fmt::print(stderr, "\n");
    fmt::print("{}", result.summary->FullReport());
  }
  fmt::print("wrote {}\n", result.run_dir.string());
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
  app->add_option("input", args->input, "Dataset folder or scene file (YAML)")
      ->required()
      ->check(kNonEmptyInput);
  app->add_option("--frontend", args->frontend,
                  "SLAM front end: memory, loop-closure candidates and acceptance (" +
                      slam::frontend::front_end_name_list() +
                      "), or external:NAME|FILE, another program run from its system file\n"
                      "on a dataset folder (shipped: " +
                      fmt::format("{}", fmt::join(interop::shipped_system_names(), ", ")) +
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
      ->check(at_least(1));
  app->add_option("--fps", args->fps, "Scene input only: frame rate (default: the scene's)")
      ->check(finite_range(0.1, 1000.0));
  app->add_option("--seed", args->scene_seed, "Scene input only: replace the scene's seed")
      ->check(kSeedValidator);
  // RTAB-Map's and ORB-SLAM2's parameters keep their defaults and are named after them here.
  app->footer("SLAM options (--set key=value; shown with their defaults):\n" +
              slam::option_reference());
  app->callback([args] { run(*args); });
}

}  // namespace wifislam::cli
