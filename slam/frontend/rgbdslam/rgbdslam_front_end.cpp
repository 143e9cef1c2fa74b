#include "slam/frontend/rgbdslam/rgbdslam_front_end.hpp"

#include <algorithm>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "slam/wifi/signature_similarity.hpp"

namespace wifislam::slam::frontend::rgbdslam {

std::vector<graph::KeyframeId> sample_without_replacement(
    const std::vector<graph::KeyframeId>& pool, int count, Rng& rng) {
  std::vector<graph::KeyframeId> remaining = pool;
  std::vector<graph::KeyframeId> out;
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

std::vector<graph::KeyframeId> sample_weighted_without_replacement(
    const std::vector<graph::KeyframeId>& pool, const std::vector<double>& weights, int count,
    Rng& rng) {
  std::vector<graph::KeyframeId> remaining = pool;
  std::vector<double> w = weights;
  std::vector<graph::KeyframeId> out;
  while (static_cast<int>(out.size()) < count && !remaining.empty()) {
    double total = 0.0;
    for (double x : w) total += x;
    // Roulette over what is left (RGBDSLAMv2 draws the same way with integer weights).
    const double pick = rng.uniform() * total;
    std::size_t chosen = remaining.size() - 1;
    double so_far = 0.0;
    for (std::size_t i = 0; i < remaining.size(); ++i) {
      so_far += w[i];
      if (pick < so_far) {
        chosen = i;
        break;
      }
    }
    out.push_back(remaining[chosen]);
    remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(chosen));
    w.erase(w.begin() + static_cast<std::ptrdiff_t>(chosen));
  }
  return out;
}

namespace {

/// RGBDSLAMv2's back end: a robust kernel on every edge in every optimisation, pruning by chi^2
/// after the run, an optimisation every `optimizer_skip_step` keyframes until converged.
FrontEndSchedule rgbdslam_schedule(const RgbdslamOptions& options) {
  FrontEndSchedule schedule;
  schedule.robustness.kernel.kind = options.robust_kernel;
  schedule.robustness.kernel.width_chi2 = options.robust_kernel_chi2;
  schedule.robustness.kernel.every_edge = true;
  schedule.robustness.pruning.chi2_thresholds = options.prune_chi2;
  schedule.optimise_every_keyframes = options.optimizer_skip_step;
  schedule.optimisation_convergence = options.optimizer_convergence;
  return schedule;
}

}  // namespace

RgbdslamFrontEnd::RgbdslamFrontEnd(const RgbdslamOptions& options, std::uint64_t seed)
    : FrontEnd("rgbdslam", std::make_unique<AcceptAllHypotheses>(), rgbdslam_schedule(options)),
      options_(options),
      wifi_long_term_candidates_(options.wifi_long_term_candidates < 0
                                     ? options.min_sampled_candidates
                                     : options.wifi_long_term_candidates),
      seed_(seed) {}

Rng RgbdslamFrontEnd::group_rng(const char* group, graph::KeyframeId keyframe) const {
  return Rng::stream(seed_, "slam/rgbdslam/" + std::string(group) + "/" + std::to_string(keyframe));
}

std::vector<Candidate> RgbdslamFrontEnd::select(const SelectionQuery& query) {
  std::vector<Candidate> out;
  const graph::KeyframeId current = query.keyframe;
  std::vector<std::uint8_t> taken(static_cast<std::size_t>(std::max(current, 0)) + 1, 0);
  taken[static_cast<std::size_t>(current)] = 1;
  for (graph::KeyframeId id : query.already_compared) {
    if (id >= 0 && id < current) taken[static_cast<std::size_t>(id)] = 1;
  }
  auto take = [&](graph::KeyframeId id, CandidateRole role) {
    if (id < 0 || id >= current || taken[static_cast<std::size_t>(id)]) return;
    taken[static_cast<std::size_t>(id)] = 1;
    out.push_back({id, role});
  };

  // (a) Predecessors: the most recent keyframes. One that tracking already compared still
  // counts as one of them, so it is marked taken before this loop and only skipped here.
  const graph::KeyframeId first_predecessor =
      std::max(0, current - options_.predecessor_candidates);
  for (graph::KeyframeId id = current - 1; id >= first_predecessor; --id) {
    take(id, CandidateRole::kPredecessor);
  }
  for (graph::KeyframeId id = first_predecessor; id < current; ++id)
    taken[static_cast<std::size_t>(id)] = 1;

  // (b) Geodesic neighbours of the previous keyframe, predecessors excluded, weighted by their
  // id distance from it.
  if (current >= 1 && query.graph != nullptr) {
    std::vector<graph::KeyframeId> neighbours;
    std::vector<double> weights;
    for (graph::KeyframeId id :
         query.graph->geodesic_neighbours(current - 1, options_.geodesic_depth)) {
      if (id < current && !taken[static_cast<std::size_t>(id)]) {
        neighbours.push_back(id);
        weights.push_back(static_cast<double>(current - 1 - id));
      }
    }
    Rng rng = group_rng("neighbours", current);
    for (graph::KeyframeId id : sample_weighted_without_replacement(
             neighbours, weights, options_.neighbor_candidates, rng)) {
      take(id, CandidateRole::kNeighbour);
    }
  }

  // (c) Long-term candidates.
  std::vector<graph::KeyframeId> eligible;
  for (graph::KeyframeId id = 0; id < current; ++id) {
    if (!taken[static_cast<std::size_t>(id)]) eligible.push_back(id);
  }
  Rng rng = group_rng("long_term", current);
  for (graph::KeyframeId id : long_term_candidates(query, eligible, rng)) {
    take(id, CandidateRole::kLongTerm);
  }
  return out;
}

std::vector<graph::KeyframeId> RgbdslamFrontEnd::long_term_candidates(
    const SelectionQuery& query, const std::vector<graph::KeyframeId>& eligible, Rng& rng) {
  if (wifi() == nullptr || !wifi()->has_signature()) {
    return sample_without_replacement(eligible, options_.min_sampled_candidates, rng);
  }
  return wifi_long_term_candidates(query, eligible, rng);
}

std::vector<graph::KeyframeId> RgbdslamFrontEnd::wifi_long_term_candidates(
    const SelectionQuery& query, const std::vector<graph::KeyframeId>& eligible, Rng& rng) {
  // Bounding: eligible keyframes of the similar clusters that qualify as a loop closure.
  std::vector<graph::KeyframeId> qualifying;
  for (graph::KeyframeId id : eligible) {
    if (query.loop_rule == nullptr || query.loop_rule->is_loop(id, query.keyframe)) {
      qualifying.push_back(id);
    }
  }
  const std::vector<graph::KeyframeId> pool = wifi()->bound(qualifying);
  // Ranking: similarity of each keyframe's own signature (shared by the keyframes of a pause, so
  // computed once per signature), then a seeded tie-break key.
  const wifi::WifiSignature& current = *wifi()->signature_of(query.keyframe);
  std::map<const wifi::WifiSignature*, double> similarity_of;
  struct Ranked {
    graph::KeyframeId keyframe;
    double similarity;
    std::uint64_t tie_break;
  };
  std::vector<Ranked> ranked;
  ranked.reserve(pool.size());
  for (graph::KeyframeId id : pool) {
    const auto signature = wifi()->signature_of(id);
    auto [it, inserted] = similarity_of.try_emplace(signature.get(), 0.0);
    if (inserted)
      it->second = wifi::cosine_similarity(current, *signature, wifi()->options().floor_dbm);
    ranked.push_back({id, it->second, rng.next_u64()});
  }
  std::sort(ranked.begin(), ranked.end(), [](const Ranked& a, const Ranked& b) {
    if (a.similarity != b.similarity) return a.similarity > b.similarity;
    if (a.tie_break != b.tie_break) return a.tie_break < b.tie_break;
    return a.keyframe < b.keyframe;
  });
  const std::size_t budget = wifi_long_term_candidates_ <= 0
                                 ? ranked.size()
                                 : std::min<std::size_t>(ranked.size(), wifi_long_term_candidates_);
  std::vector<graph::KeyframeId> out;
  for (std::size_t i = 0; i < budget; ++i) out.push_back(ranked[i].keyframe);
  return out;
}

nlohmann::json RgbdslamFrontEnd::own_summary() const {
  nlohmann::json out = {{"predecessor_candidates", options_.predecessor_candidates},
                        {"neighbor_candidates", options_.neighbor_candidates},
                        {"min_sampled_candidates", options_.min_sampled_candidates},
                        {"optimizer_skip_step", options_.optimizer_skip_step}};
  if (wifi() != nullptr) out["wifi_long_term_candidates"] = wifi_long_term_candidates_;
  return out;
}

}  // namespace wifislam::slam::frontend::rgbdslam
