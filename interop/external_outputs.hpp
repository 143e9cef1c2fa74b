#pragma once
// What an external system wrote (external_system.hpp's outputs, in its own folder) turned into a
// run folder's files (core/run_format.hpp), so that eval reads an external run like ours:
//   trajectory   -> trajectory.txt     read and written back as TUM (a file eval can read)
//   keyframes    -> keyframes.txt      likewise; without one, when the system reports loop
//                                      closures but no graph, every trajectory pose is a keyframe
//   loop_closures -> loop_closures.csv our columns; the system's file has our columns, or at
//                                      least from_time and to_time (and optionally tx ty tz qx
//                                      qy qz qw, role, inliers): each stamp is matched to the
//                                      keyframe within 0.02 s, and a closure without a pose gets
//                                      the relative pose of its keyframes in the estimate
//   graph        -> graph.json         copied (our format; eval checks it)
//   wifi_clusters -> wifi_clusters.csv copied (our format; eval checks it), Wi-Fi variant only
//   time_log     -> timing.json        {"loop_closure_detection_s", "optimisation_s"} as modules,
//                                      with the run's measured total and wall-clock
// Nothing outside the system's folder is read.

#include <filesystem>
#include <string>

#include "interop/external_system.hpp"

namespace wifislam::interop {

struct ImportedOutputs {
  std::int64_t frames = 0, keyframes = 0, loop_closures = 0;
  bool graph = false;
};

/// Imports the outputs of `system` from `system_out` into `run_dir` (both existing folders), with
/// `cpu_s` and `wall_s` the run's measured times; `wifi` says the run was the Wi-Fi variant. Throws
/// ParseError naming the system's file and line for an output that is missing or malformed (the
/// caller turns it into the run's status).
ImportedOutputs import_external_outputs(const ExternalSystem& system,
                                        const std::filesystem::path& system_out,
                                        const std::filesystem::path& run_dir, bool wifi,
                                        double cpu_s, double wall_s);

}  // namespace wifislam::interop
