// `wifislam generate <scene.yaml> -o <dir>`: render a scene's route into a TUM-compatible
// dataset with Wi-Fi scans, wheel odometry and exact ground truth.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "apps/command_registry.hpp"
#include "apps/option_validators.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "core/stop_signal.hpp"
#include "radio_model/receiver_device.hpp"
#include "sim/generate/dataset_writer.hpp"
#include "sim/scene/scene_loader.hpp"

namespace wifislam::cli {

namespace {

struct GenerateArgs {
  std::string scene_path;
  std::string output;
  std::optional<std::uint64_t> seed;
  std::optional<double> fps;
  std::string device;
  std::optional<std::uint64_t> session;
  std::int64_t max_frames = -1;
  bool no_images = false;
  int threads = 0;
  bool force = false;
  bool quiet = false;
};

// A one-line bar redrawn in place; only used when stderr is a terminal.
void draw_progress(const sim::generate::GenerateProgress& p) {
  const int width = 30;
  const double f = p.frames_total > 0 ? static_cast<double>(p.frames_done) / p.frames_total : 1.0;
  const int filled = static_cast<int>(f * width);
  const double rate = p.elapsed_s > 0 ? p.frames_done / p.elapsed_s : 0.0;
  const double eta_s = rate > 0 ? (p.frames_total - p.frames_done) / rate : 0.0;
  fmt::print(stderr, "\r[{}{}] {}/{} frames  {:.1f} fps  ETA {:.0f} s ", std::string(filled, '#'),
             std::string(width - filled, ' '), p.frames_done, p.frames_total, rate, eta_s);
  if (p.frames_done == p.frames_total) fmt::print(stderr, "\n");
}

void run_generate(const GenerateArgs& args) {
  std::vector<std::filesystem::path> inputs{args.scene_path};
  if (std::filesystem::exists(args.device)) inputs.push_back(args.device);
  const bool replace = check_output_folder({args.output, args.force, {}, inputs});
  sim::scene::Scene scene = sim::scene::load_scene_file(args.scene_path);
  if (args.session) scene.session = *args.session;
  if (!args.device.empty()) {
    try {
      scene.sensors.wifi.device = sim::scene::load_receiver_device(args.device);
    } catch (const InvalidInputError& e) {
      throw InvalidInputError(fmt::format("--device: {}", e.what()));
    }
  }
  sim::generate::GenerateOptions options;
  options.seed = args.seed;
  options.fps = args.fps;
  options.max_frames = args.max_frames;
  options.camera = args.no_images ? sim::generate::CameraOutput::kNoImages
                                  : sim::generate::CameraOutput::kColourAndDepth;
  options.threads = args.threads;
  options.overwrite = replace;
  const bool draw = cli::stderr_is_tty() && !args.quiet;
  std::int64_t last_drawn = -1;
  options.on_progress = [draw, last_drawn](const sim::generate::GenerateProgress& p) mutable {
    throw_if_stop_requested();
    // Redraw at most ~200 times per run.
    const std::int64_t step = std::max<std::int64_t>(1, p.frames_total / 200);
    if (draw && (p.frames_done == p.frames_total || p.frames_done - last_drawn >= step)) {
      draw_progress(p);
      last_drawn = p.frames_done;
    }
  };
  const StopOnSignal stop_on_signal;  // Ctrl-C removes the unfinished dataset
  const sim::generate::GenerateSummary summary =
      sim::generate::generate_dataset(scene, args.output, options);
  if (!args.quiet) fmt::print("{}", summary.full_report());
}

}  // namespace

WIFISLAM_COMMAND(generate, 50) {
  auto args = std::make_shared<GenerateArgs>();
  CLI::App* app = parent.add_subcommand(
      "generate",
      "Generate a dataset from a scene: RGB-D frames along the robot's route (TUM RGB-D layout),\n"
      "Wi-Fi scans during the robot's pauses (wifi.csv), wheel odometry and exact ground truth.");
  app->footer(
      "Frame rate: the camera runs at the scene's sensors.camera.fps (default 30, the Kinect's).\n"
      "Lower it with --fps (e.g. --fps 5) or in the scene file to get proportionally fewer frames\n"
      "over the same route: the robot's motion, pauses, Wi-Fi scans and odometry do not change.\n"
      "--max-frames cuts the run short instead. --no-images skips rendering (poses, odometry and\n"
      "Wi-Fi only) for fast radio studies.\n"
      "Stamps are Unix time: the route starts at the scene's sensors.time_origin_s (default\n"
      "1700000000 s = 2023-11-14 22:13:20 UTC; 0 for times from 0 s), so peers that want real\n"
      "sensor stamps (RTAB-Map reads them from the image names) take the dataset as it is.\n"
      "The folder is written as <dir>.partial and renamed when complete; the output is\n"
      "byte-identical for the same scene, seed and options whatever --threads is.");
  app->add_option("scene", args->scene_path, "Scene file (YAML)")
      ->required()
      ->check(kNonEmptyInput);  // the scene loader says what is wrong with the path
  app->add_option("-o,--output", args->output, "Dataset folder to create")->required();
  app->add_option("--seed", args->seed, "Replace the scene's seed")->check(kSeedValidator);
  app->add_option("--fps", args->fps, "Camera frame rate (default: the scene's, 30)")
      ->check(finite_range(0.1, 1000.0));
  app->add_option("--max-frames", args->max_frames, "Stop after this many frames")
      ->check(at_least(1));
  std::string shipped;
  for (const auto& device : radio_model::shipped_devices())
    shipped += (shipped.empty() ? "" : ", ") + device.name;
  app->add_option("--device", args->device,
                  "The Wi-Fi receiver, in place of the scene's sensors.wifi.device: a shipped\n"
                  "device (" +
                      shipped +
                      ")\n"
                      "or a device file (*.yaml; scenes/README.md lists its keys)")
      ->check(kNonEmptyDevice);
  app->add_option("--session", args->session,
                  "Which visit of the building to render (default: the scene's `session`, else\n"
                  "0): the same building, route and appearance, with the scene's\n"
                  "access_points.changes up to this session applied; the robot's pauses, the\n"
                  "sensors' noise and the Wi-Fi draws are the session's own")
      ->check(CLI::Range(std::uint64_t{0}, std::uint64_t{1000000}));
  app->add_flag("--no-images", args->no_images, "Write poses, odometry and Wi-Fi only");
  app->add_option("--threads", args->threads,
                  "PNG encoding threads (default: one per core; at most 4 per core, fewer if the\n"
                  "system will not start more)")
      ->check(at_least(0));
  app->add_flag("--force", args->force,
                "Replace the output folder if it exists and holds this tool's output (never an\n"
                "input, the current directory, the home folder or a folder of your own)");
  app->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  app->callback([args] { run_generate(*args); });
}

}  // namespace wifislam::cli
