#pragma once
// An external SLAM or localisation program described by a system file (systems/*.yaml, format in
// docs/external_systems.md), so that compare and studies run it beside our front ends and eval
// scores it like ours:
//
//   version: 1
//   name: opencv_rgbd_odometry
//   description: ...          # optional
//   command: [/usr/bin/python3, "{system_dir}/opencv_rgbd_odometry.py", "{dataset}", "{out}"]
//   timeout_s: 3600           # optional, default 3600
//   wifi: false               # reads wifi.csv: its Wi-Fi variant runs
//   export: orbslam2          # needed by {rgbd_export}: rtabmap or orbslam2
//   outputs:                  # files it writes, relative to {out}
//     trajectory: trajectory.txt         # TUM, camera-to-map (required)
//     keyframes: keyframes.txt           # TUM (optional; required with graph)
//     loop_closures: loop_closures.csv   # accepted closures (optional)
//     graph: graph.json                  # our graph.json format (optional)
//     time_log: time.json                # {"loop_closure_detection_s": ...} (optional)
//     wifi_clusters: wifi_clusters.csv   # our format, Wi-Fi variant only (optional)
//
// The command is a list of arguments, run without a shell (a single string is split at spaces,
// with '...' or "..." keeping spaces inside one argument). Placeholders, replaced inside every
// argument: {dataset} the dataset folder (TUM layout with wifi.csv), {rgbd_export} the dataset
// laid out for the `export` peer, {out} the folder the program writes into (its working folder,
// empty at the start), {seed}, {wifi} (true/false), {system_dir} the system file's folder,
// {wifislam} this wifislam binary. A literal brace is written {{ or }}.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/run_format.hpp"
#include "interop/peer_export.hpp"

namespace wifislam::interop {

/// The prefix that names an external system where a front end is expected
/// (`--frontend external:NAME`, a study's `frontend` or `system` axis).
inline constexpr const char* kExternalPrefix = run_folder::kExternalFrontendPrefix;

struct ExternalSystem {
  std::filesystem::path file;  // the system file, absolute
  std::string name, description;
  std::vector<std::string> command;  // with placeholders
  double timeout_s = 3600.0;
  bool wifi = false;
  std::optional<Peer> export_for;
  std::string trajectory = "trajectory.txt";
  std::string keyframes, loop_closures, graph, time_log;  // empty: not written
  std::string wifi_clusters;  // written by the Wi-Fi variant only; empty: not written
};

/// Reads and checks a system file. Throws IoError when it cannot be read, ParseError naming
/// file:line:column and the key for anything else (unknown key with the closest, unknown
/// placeholder, output paths that leave {out}, {rgbd_export} without `export`).
ExternalSystem load_external_system(const std::filesystem::path& file);

/// True when a front-end name names an external system ("external:...").
bool is_external_frontend(const std::string& frontend);

/// The system named by "external:X": X is a system file (a path, or a name ending in .yaml), else
/// the name of a shipped system (systems/X.yaml). Throws as load_external_system, or
/// InvalidInputError listing the shipped systems when there is no such name.
ExternalSystem resolve_external_system(const std::string& frontend);

/// The user's system file "external:X" names (X, when it is a path or ends in .yaml; a command's
/// output folder must not hold it), or empty for a shipped system's name or any other front end.
std::filesystem::path user_system_file(const std::string& frontend);

/// The shipped systems' names (systems/*.yaml).
std::vector<std::string> shipped_system_names();

/// Values of the placeholders for one run.
struct ExternalRunValues {
  std::filesystem::path dataset, rgbd_export, out, wifislam_binary;
  std::uint64_t seed = 1;
  bool wifi = false;
};

/// The command's arguments with every placeholder replaced.
std::vector<std::string> expand_command(const ExternalSystem& system,
                                        const ExternalRunValues& values);

}  // namespace wifislam::interop
