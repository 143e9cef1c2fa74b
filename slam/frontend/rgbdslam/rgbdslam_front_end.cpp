#include "slam/frontend/rgbdslam/rgbdslam_front_end.hpp"

#include <algorithm>

namespace wifislam::slam {

std::vector<KeyframeId> sample_without_replacement(const std::vector<KeyframeId>& pool, int count,
                                                   Rng& rng) {
  std::vector<KeyframeId> remaining = pool;
  std::vector<KeyframeId> out;
  const auto n =
      std::min<std::size_t>(remaining.size(), static_cast<std::size_t>(std::max(0, count)));
  for (std::size_t i = 0; i < n; ++i) {
    // Partial Fisher-Yates with the project's portable generator.
    const auto j = static_cast<std::size_t>(rng.uniform_int(
        static_cast<std::int64_t>(i), static_cast<std::int64_t>(remaining.size()) - 1));
    std::swap(remaining[i], remaining[j]);
    out.push_back(remaining[i]);
  }
  return out;
}

RgbdslamFrontEnd::RgbdslamFrontEnd(const RgbdslamOptions& options, int wifi_long_term_candidates,
                                   std::uint64_t seed)
    : FrontEnd(std::make_unique<AcceptAllHypotheses>()),
      options_(options),
      wifi_long_term_candidates_(wifi_long_term_candidates),
      rng_(Rng::stream(seed, "slam/rgbdslam/candidates")),
      wifi_rng_(Rng::stream(seed, "slam/wifi/candidates")) {}

std::vector<Candidate> RgbdslamFrontEnd::select(const SelectionQuery& query) {
  // Wi-Fi clustering: the new keyframe's signature and its similar clusters.
  if (wifi() != nullptr) wifi()->sign(query.keyframe);

  std::vector<Candidate> out;
  const KeyframeId current = query.keyframe;
  std::vector<std::uint8_t> taken(static_cast<std::size_t>(std::max(current, 0)) + 1, 0);
  taken[static_cast<std::size_t>(current)] = 1;
  for (KeyframeId id : query.already_compared) {
    if (id >= 0 && id < current) taken[static_cast<std::size_t>(id)] = 1;
  }
  auto take = [&](KeyframeId id, CandidateRole role) {
    if (id < 0 || id >= current || taken[static_cast<std::size_t>(id)]) return;
    taken[static_cast<std::size_t>(id)] = 1;
    out.push_back({id, role});
  };

  // (a) Predecessors: the most recent keyframes. One that tracking already compared still
  // counts as one of them, so it is marked taken before this loop and only skipped here.
  const KeyframeId first_predecessor = std::max(0, current - options_.predecessor_candidates);
  for (KeyframeId id = current - 1; id >= first_predecessor; --id) {
    take(id, CandidateRole::kPredecessor);
  }
  for (KeyframeId id = first_predecessor; id < current; ++id)
    taken[static_cast<std::size_t>(id)] = 1;

  // (b) Geodesic neighbours of the previous keyframe.
  if (current >= 1 && query.graph != nullptr) {
    std::vector<KeyframeId> neighbours;
    for (KeyframeId id : query.graph->geodesic_neighbours(current - 1, options_.geodesic_depth)) {
      if (id < current && !taken[static_cast<std::size_t>(id)]) neighbours.push_back(id);
    }
    for (KeyframeId id :
         sample_without_replacement(neighbours, options_.neighbor_candidates, rng_)) {
      take(id, CandidateRole::kNeighbour);
    }
  }

  // (c) Long-term candidates.
  std::vector<KeyframeId> eligible;
  for (KeyframeId id = 0; id < current; ++id) {
    if (!taken[static_cast<std::size_t>(id)]) eligible.push_back(id);
  }
  for (KeyframeId id : long_term_candidates(query, eligible)) take(id, CandidateRole::kLongTerm);
  return out;
}

std::vector<KeyframeId> RgbdslamFrontEnd::long_term_candidates(
    const SelectionQuery& query, const std::vector<KeyframeId>& eligible) {
  if (wifi() == nullptr || !wifi()->has_signature()) {
    return sample_without_replacement(eligible, options_.min_sampled_candidates, rng_);
  }
  // Bounding: eligible keyframes old enough for a match to be a loop closure, kept when they
  // belong to a similar cluster.
  const int gap = query.loop_rule != nullptr ? query.loop_rule->min_keyframe_gap() : 0;
  std::vector<KeyframeId> old_enough;
  for (KeyframeId id : eligible) {
    if (query.keyframe - id < gap) break;
    old_enough.push_back(id);
  }
  const std::vector<KeyframeId> pool = wifi()->bound(old_enough);
  if (wifi_long_term_candidates_ <= 0) return pool;
  return sample_without_replacement(pool, wifi_long_term_candidates_, wifi_rng_);
}

nlohmann::json RgbdslamFrontEnd::own_summary() const {
  nlohmann::json out = {{"predecessor_candidates", options_.predecessor_candidates},
                        {"neighbor_candidates", options_.neighbor_candidates},
                        {"min_sampled_candidates", options_.min_sampled_candidates}};
  if (wifi() != nullptr) out["wifi_sampled_candidates"] = wifi_long_term_candidates_;
  return out;
}

}  // namespace wifislam::slam
