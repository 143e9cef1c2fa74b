#pragma once
// Which front ends a comparison or a study may name: ours (slam/frontend/front_end_registry.hpp)
// and external systems ("external:NAME|FILE", interop/external_system.hpp). Checked before any
// dataset is generated, so a typo or a broken system file costs nothing.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "slam/slam_options.hpp"

namespace wifislam::study {

/// The front end a study's `system` axis value names: one of ours as itself, "external:X" as
/// itself, any other value X as the external system "external:X" (a shipped name or a file).
std::string system_front_end(const std::string& value);

/// Why `frontend` cannot run (unknown name with the known ones, or the system file's own error),
/// or nothing when it can.
std::optional<std::string> front_end_problem(const std::string& frontend);

/// The user's files a run with `options` reads besides its input: the ORB vocabulary and an
/// external system's file. A command's output folder must not hold them: --force would delete
/// them with it (core/output_folder.hpp).
std::vector<std::filesystem::path> files_read_by(const slam::SlamOptions& options);

}  // namespace wifislam::study
