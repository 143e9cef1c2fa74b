#include "eval/run_divergence.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "core/run_format.hpp"
#include "core/tum_trajectory.hpp"
#include "eval/graph_edges_json.hpp"

namespace wifislam::eval {

namespace {

/// Per keyframe, its accepted edges from earlier keyframes as sorted (from, type) pairs.
std::vector<std::vector<std::pair<std::int64_t, std::string>>> edges_by_keyframe(
    const std::filesystem::path& run, std::size_t keyframes) {
  std::vector<std::vector<std::pair<std::int64_t, std::string>>> out(keyframes);
  for (const GraphEdgeRecord& e : read_graph_edges_json(run / run_folder::kGraph)) {
    const std::int64_t later = std::max(e.from_keyframe, e.to_keyframe);
    const std::int64_t earlier = std::min(e.from_keyframe, e.to_keyframe);
    if (later >= 0 && static_cast<std::size_t>(later) < keyframes) {
      out[static_cast<std::size_t>(later)].emplace_back(earlier, e.type);
    }
  }
  for (auto& edges : out) std::sort(edges.begin(), edges.end());
  return out;
}

}  // namespace

std::optional<RunDivergence> first_divergence(const std::filesystem::path& run_a,
                                              const std::filesystem::path& run_b) {
  const Trajectory a = read_tum_trajectory((run_a / run_folder::kKeyframes).string());
  const Trajectory b = read_tum_trajectory((run_b / run_folder::kKeyframes).string());
  const auto edges_a = edges_by_keyframe(run_a, a.size());
  const auto edges_b = edges_by_keyframe(run_b, b.size());
  const std::size_t common = std::min(a.size(), b.size());
  for (std::size_t k = 0; k < common; ++k) {
    if (a[k].time != b[k].time || edges_a[k] != edges_b[k]) {
      return RunDivergence{static_cast<std::int64_t>(k), a[k].time.seconds_since(a[0].time)};
    }
  }
  if (a.size() == b.size()) return std::nullopt;
  const Trajectory& longer = a.size() > b.size() ? a : b;
  return RunDivergence{static_cast<std::int64_t>(common),
                       longer[common].time.seconds_since(longer[0].time)};
}

}  // namespace wifislam::eval
