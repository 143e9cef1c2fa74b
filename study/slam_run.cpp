#include "study/slam_run.hpp"

#include <memory>

#include <fmt/core.h>

#include "core/dataset_recording.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "sim/generate/sensor_input.hpp"
#include "slam/io/run_folder_writer.hpp"
#include "slam/system/run_slam.hpp"
#include "study/front_end_choice.hpp"

namespace wifislam::study {

namespace fs = std::filesystem;

namespace {

/// An external system (external:X) on a dataset folder, through its system file.
SlamRunResult run_external_to_folder(const SlamRunRequest& request, bool replace,
                                     SlamRunResult result) {
  const slam::SlamOptions& options = request.options;
  if (!fs::is_directory(request.input)) {
    throw InvalidInputError(request.input.string() +
                            ": an external system reads a dataset folder; generate "
                            "one from the scene first (wifislam generate)");
  }
  if (request.max_frames >= 0 || request.fps || request.scene_seed) {
    throw ParseError("--frontend", options.frontend,
                     "--max-frames, --fps and --seed apply to our front ends; an external system "
                     "reads the whole dataset (its seed is --set seed=N)");
  }
  interop::ExternalRunRequest external = interop::external_run_request(
      options.frontend, options.wifi.enabled, request.input, request.output);
  external.overwrite = replace;
  external.seed = options.seed;
  external.extra_run_info = {
      {"input", dataset_run_input(request.input, recording_of_dataset(request.input))}};
  result.external = interop::run_external_system(external);
  result.external_system_file = external.system.file.string();
  if (!result.external->ok) {
    throw ExternalSystemError(fmt::format(
        "{} ({}): {}; its run folder {} has run.json, stdout.log and stderr.log", options.frontend,
        result.external_system_file, result.external->status, result.run_dir.string()));
  }
  return result;
}

}  // namespace

SlamRunResult run_slam_to_folder(const SlamRunRequest& request) {
  slam::validate(request.options);
  std::vector<std::filesystem::path> inputs = files_read_by(request.options);
  inputs.push_back(request.input);
  const bool replace = check_output_folder({request.output, request.force, {}, inputs});
  SlamRunResult result;
  result.run_dir = absolute_folder(request.output);
  if (interop::is_external_frontend(request.options.frontend)) {
    return run_external_to_folder(request, replace, std::move(result));
  }
  sim::generate::SensorInputOptions input_options;
  input_options.verify_checksums = request.verify_checksums;
  input_options.max_frames = request.max_frames;
  input_options.fps = request.fps;
  input_options.scene_seed = request.scene_seed;
  sim::generate::SensorInput input = sim::generate::open_sensor_input(request.input, input_options);
  slam::system::RunSummary summary;
  const std::unique_ptr<slam::system::SlamSystem> system =
      slam::system::run_slam(*input.stream, request.options, summary, request.on_frame);
  slam::io::write_run_folder(request.output, *system, summary, replace,
                             {{"input", input.description}});
  result.summary = std::move(summary);
  return result;
}

}  // namespace wifislam::study
