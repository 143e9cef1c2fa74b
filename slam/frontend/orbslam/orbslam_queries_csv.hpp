#pragma once
// orbslam_queries.csv, the orbslam front end's own file in its run folder: one row per keyframe
// (its loop detection: indexes and keyframes searched, postings read, candidates at each stage).
// The rest of the run folder is core/run_format.hpp's.

#include <array>

namespace wifislam::slam::frontend::orbslam::orbslam_queries_csv {

inline constexpr const char* kFileName = "orbslam_queries.csv";

/// Columns of orbslam_queries.csv, in order (slam/frontend/orbslam/orbslam_front_end.hpp,
/// OrbslamQueryRecord); query_ms is wall-clock, the rest is exact.
namespace column {
// clang-format off
inline constexpr std::array<const char*, 12> kAll = {
    "keyframe", "detection_ran", "databases_searched", "keyframes_searched", "postings_read",
    "min_score", "candidates", "consistent", "bow_passed", "accepted_loop", "cluster",
    "query_ms"};
// clang-format on
}  // namespace column

}  // namespace wifislam::slam::frontend::orbslam::orbslam_queries_csv
