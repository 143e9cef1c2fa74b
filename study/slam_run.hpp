#pragma once
// A SLAM run of a dataset folder or a scene file into a run folder: what `wifislam slam` does,
// in one place for the command line and the Python module (python/). Our front ends read the
// input through sim::generate::open_sensor_input; an external system (`external:X`) is run on a
// dataset folder from its system file (interop/external_run.hpp).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "interop/external_run.hpp"
#include "slam/slam_options.hpp"
#include "slam/system/run_summary.hpp"

namespace wifislam::study {

struct SlamRunRequest {
  std::filesystem::path input;   // dataset folder or scene file
  std::filesystem::path output;  // run folder to write
  slam::SlamOptions options;     // validated by run_slam_to_folder
  bool force = false;            // replace an existing run folder (core/output_folder.hpp)
  bool verify_checksums = true;
  // Our front ends only (an external system reads the whole dataset).
  std::int64_t max_frames = -1;
  std::optional<double> fps;                // scene input only
  std::optional<std::uint64_t> scene_seed;  // scene input only
  /// Called with the frame count after each frame (our front ends), from the calling thread.
  std::function<void(std::int64_t frames)> on_frame;
};

struct SlamRunResult {
  std::filesystem::path run_dir;                       // absolute, normalised
  std::optional<slam::system::RunSummary> summary;     // our front ends
  std::optional<interop::ExternalRunResult> external;  // an external system (always ok: see below)
  std::string external_system_file;                    // the system file an external run used
};

/// Runs and writes the run folder. Throws the option, input and output errors the CLI reports
/// (InvalidInputError, ParseError, IoError), and ExternalSystemError when an external system
/// fails (its run folder keeps run.json, stdout.log and stderr.log).
SlamRunResult run_slam_to_folder(const SlamRunRequest& request);

}  // namespace wifislam::study
