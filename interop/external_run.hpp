#pragma once
// One run of an external system (external_system.hpp) on a dataset, written as a run folder that
// eval reads like ours (core/run_format.hpp):
//
//   system/            the system's working folder ({out}): everything it wrote, as it wrote it
//   rgbd_export/       the dataset laid out for the system's peer, when its command uses one
//   stdout.log, stderr.log
//   trajectory.txt, keyframes.txt, loop_closures.csv, graph.json, timing.json
//                      imported from its outputs (external_outputs.hpp)
//   run.json           "frontend": "external:<name>", "wifi", and "external": the command as run,
//                      its status, exit code, wall-clock and CPU time, the tails of its stdout and
//                      stderr
//
// A run that fails (does not start, exits non-zero, is killed, times out, or writes no usable
// trajectory) is still a run folder, with the reason as run.json's status and no trajectory.txt:
// the caller reports it as a failed row, it never ends a comparison or a study.

#include <cstdint>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "core/final_paths.hpp"
#include "interop/external_system.hpp"
#include "interop/process_runner.hpp"

namespace wifislam::interop {

struct ExternalRunRequest {
  ExternalSystem system;
  std::filesystem::path dataset;  // a dataset folder (ours or plain TUM)
  std::filesystem::path run_dir;  // the run folder to write (atomically)
  bool overwrite = false;         // the caller applied core/output_folder.hpp's rule
  std::uint64_t seed = 1;
  bool wifi = false;
  /// Merged into run.json (e.g. {"input": {...}}), as for our own runs.
  nlohmann::json extra_run_info = nlohmann::json::object();
  /// The folder under construction that holds run_dir and the dataset (a comparison's): run.json
  /// and the status name where they will be once it is committed.
  FinalPaths within;
};

struct ExternalRunResult {
  bool ok = false;     // the system exited 0 and its outputs were imported
  std::string status;  // "ok", or why not ("exited 1", "timed out after 60 s", "no trajectory")
  ProcessResult process;
};

/// The request to run the external front end `frontend` ("external:X", resolved as
/// resolve_external_system does) on `dataset` into `run_dir`. Throws InvalidInputError when the
/// Wi-Fi variant is asked of a system that reads no Wi-Fi.
ExternalRunRequest external_run_request(const std::string& frontend, bool wifi,
                                        const std::filesystem::path& dataset,
                                        const std::filesystem::path& run_dir);

/// Runs the system and writes the run folder. Throws only for what is the caller's mistake or
/// the machine's (the dataset missing, the run folder not writable); everything the system does
/// wrong is the result's status.
ExternalRunResult run_external_system(const ExternalRunRequest& request);

}  // namespace wifislam::interop
