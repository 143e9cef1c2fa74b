#pragma once
// rtabmap_memory.csv, the rtabmap front end's own file in its run folder: one row per node
// (memory sizes, transfers, retrievals, hypothesis, time over budget). The rest of the run folder
// is core/run_format.hpp's.

#include <array>

namespace wifislam::slam::frontend::rtabmap::rtabmap_memory_csv {

inline constexpr const char* kFileName = "rtabmap_memory.csv";

/// Columns of rtabmap_memory.csv, in order (slam/frontend/rtabmap/rtabmap_front_end.hpp,
/// RtabmapNodeRecord). Sizes are after the node's memory management; times in ms.
namespace column {
// clang-format off
inline constexpr std::array<const char*, 32> kAll = {
    "node", "stm", "wm", "ltm",
    "entered_wm", "retrieved", "wifi_retrieved", "transferred", "immune", "rehearsed",
    "words", "word_comparisons", "scored", "likelihood_terms", "hypotheses",
    "best", "best_probability", "virtual_probability",
    "loop_candidate", "loop_verified", "loop_accepted", "verifications", "loop_verifications",
    "proximity_candidates",
    "memory_update_cpu_ms", "likelihood_cpu_ms", "posterior_cpu_ms", "loop_closure_cost_ms",
    "cost_ms", "wall_ms", "cpu_ms", "over_budget_ms"};
// clang-format on
}  // namespace column

}  // namespace wifislam::slam::frontend::rtabmap::rtabmap_memory_csv
