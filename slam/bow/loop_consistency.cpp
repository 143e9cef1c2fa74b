#include "slam/bow/loop_consistency.hpp"

#include <algorithm>

namespace wifislam::slam::bow {

std::vector<graph::KeyframeId> LoopConsistency::update(
    const std::vector<std::pair<graph::KeyframeId, std::set<graph::KeyframeId>>>& candidates) {
  std::vector<graph::KeyframeId> enough;
  std::vector<std::pair<std::set<graph::KeyframeId>, int>> current;
  std::vector<bool> extended(kept_.size(), false);
  for (const auto& [candidate, group] : candidates) {
    bool enough_consistent = false, consistent_with_some = false;
    for (std::size_t g = 0; g < kept_.size(); ++g) {
      const std::set<graph::KeyframeId>& previous = kept_[g].first;
      const bool shares = std::any_of(group.begin(), group.end(),
                                      [&](graph::KeyframeId k) { return previous.count(k) > 0; });
      if (!shares) continue;
      consistent_with_some = true;
      const int count = kept_[g].second + 1;
      if (!extended[g]) {
        current.emplace_back(group, count);
        extended[g] = true;
      }
      if (count >= threshold_ && !enough_consistent) {
        enough.push_back(candidate);
        enough_consistent = true;
      }
    }
    if (!consistent_with_some) current.emplace_back(group, 0);
  }
  kept_ = std::move(current);
  return enough;
}

}  // namespace wifislam::slam::bow
