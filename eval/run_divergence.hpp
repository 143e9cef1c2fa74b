#pragma once
// Where two runs of one dataset part ways: the first keyframe whose time, or whose set of
// accepted edges (earlier keyframe and type), differs between them. The vanilla and Wi-Fi runs
// of a comparison draw their random candidates from the same per-keyframe sub-streams, so up to
// this keyframe they are the same run, and this is where Wi-Fi first changed something.

#include <cstdint>
#include <filesystem>
#include <optional>

namespace wifislam::eval {

struct RunDivergence {
  std::int64_t keyframe = -1;  // first keyframe that differs
  /// Its time in the run that has it, since that run's first keyframe (stamps are Unix times).
  double time_s = 0.0;
};

/// Reads keyframes.txt and graph.json of both run folders. nullopt when the runs agree on every
/// keyframe and edge. Throws IoError / ParseError naming the file.
std::optional<RunDivergence> first_divergence(const std::filesystem::path& run_a,
                                              const std::filesystem::path& run_b);

}  // namespace wifislam::eval
