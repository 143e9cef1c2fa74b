#include "study/greedy_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/median.hpp"
#include "core/rng.hpp"
#include "sim/site/ap_placement.hpp"
#include "sim/site/site.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::study {

namespace {

double coarseness(const RadioResolution& r) {
  return r.resolution_m.value_or(std::numeric_limits<double>::infinity());
}

/// Each pause's readings per candidate: (candidate index, RSSI) sorted by candidate.
struct PauseReadings {
  Eigen::Vector2d position_m;
  std::vector<std::pair<int, double>> rssi_dbm;
};

/// The pauses of a placement: each pause's signature restricted to the chosen candidates.
std::vector<PauseSample> restrict_to(const std::vector<PauseReadings>& pauses,
                                     const std::vector<slam::wifi::AccessPointKey>& keys,
                                     const std::vector<bool>& chosen) {
  std::vector<PauseSample> out;
  out.reserve(pauses.size());
  for (const PauseReadings& p : pauses) {
    std::vector<slam::wifi::ApStrength> strengths;
    for (const auto& [candidate, rssi] : p.rssi_dbm)
      if (chosen[static_cast<std::size_t>(candidate)])
        strengths.push_back({keys[static_cast<std::size_t>(candidate)], rssi});
    out.push_back({p.position_m, slam::wifi::WifiSignature(std::move(strengths))});
  }
  return out;
}

}  // namespace

double placement_error(const RadioResolution& r) {
  return (1.0 - r.near_similar_share) + r.far_similar_share;
}

bool places_better(const RadioResolution& a, const RadioResolution& b) {
  if (placement_error(a) != placement_error(b)) return placement_error(a) < placement_error(b);
  return coarseness(a) < coarseness(b);
}

namespace {

/// The candidate positions of the site's plan; InvalidInputError when there are too many or
/// fewer than the budget.
std::vector<Eigen::Vector2d> candidate_spots(const sim::site::Site& site,
                                             const PlacementOptions& options) {
  const std::vector<Eigen::Vector2d> spots =
      sim::site::access_point_candidate_spots(site.world().plan, options.candidate_spacing_m);
  if (static_cast<int>(spots.size()) > kMaxPlacementCandidates) {
    throw InvalidInputError(
        fmt::format("{} candidate positions at {} m spacing (at most {}): give a larger --spacing",
                    spots.size(), options.candidate_spacing_m, kMaxPlacementCandidates));
  }
  if (options.budget < 1 || options.budget > static_cast<int>(spots.size())) {
    throw InvalidInputError(fmt::format(
        "--budget {}: the plan has {} candidate positions at {} m spacing (give 1 to {}, or a "
        "smaller --spacing)",
        options.budget, spots.size(), options.candidate_spacing_m, spots.size()));
  }
  return spots;
}

/// Every pause's readings of an access point at every candidate: one simulation on the same
/// building and route (`keys` receives each candidate's signature key, in candidate order).
std::vector<PauseReadings> simulate_candidates(const sim::site::Site& site,
                                               const PlacementResult& result,
                                               const PlacementOptions& options,
                                               std::vector<slam::wifi::AccessPointKey>& keys) {
  sim::scene::AccessPoints all = site.scene().access_points;
  all.placement = sim::scene::ApPlacement::kExplicit;
  all.explicit_list.clear();
  for (const Eigen::Vector3d& position_m : result.candidates) {
    sim::scene::AccessPointSpec spec;
    spec.position_m = position_m;  // z above the level's floor
    spec.level = result.level;
    all.explicit_list.push_back(spec);
  }
  all.count = static_cast<int>(result.candidates.size());
  const std::vector<PauseSample> every = simulate_pauses(
      std::make_shared<const sim::site::Site>(site.with_access_points(all)), options.wifi, &keys);
  std::map<slam::wifi::AccessPointKey, int> candidate_of;
  for (std::size_t i = 0; i < keys.size(); ++i) candidate_of[keys[i]] = static_cast<int>(i);
  std::vector<PauseReadings> pauses;
  for (const PauseSample& p : every) {
    PauseReadings r{p.position_m, {}};
    for (const slam::wifi::ApStrength& s : p.signature.strengths())
      r.rssi_dbm.emplace_back(candidate_of.at(s.ap), s.rssi_dbm);
    std::sort(r.rssi_dbm.begin(), r.rssi_dbm.end());
    pauses.push_back(std::move(r));
  }
  return pauses;
}

/// The medians of `random_draws` placements of k candidates drawn uniformly without replacement
/// (stream "study/place/random/<k>/<draw>"), into `step`.
void random_baseline(const std::vector<PauseReadings>& pauses,
                     const std::vector<slam::wifi::AccessPointKey>& keys, int k,
                     const PlacementOptions& options, PlacementStep& step) {
  const std::size_t n = keys.size();
  std::vector<double> error, resolution, far, near;
  for (int draw = 0; draw < options.random_draws; ++draw) {
    Rng rng = Rng::stream(options.seed, fmt::format("study/place/random/{}/{}", k, draw));
    std::vector<int> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<int>(i);
    std::vector<bool> random_set(n, false);
    for (int i = 0; i < k; ++i) {  // partial Fisher-Yates
      const auto j = static_cast<std::size_t>(rng.uniform_int(i, static_cast<std::int64_t>(n) - 1));
      std::swap(order[static_cast<std::size_t>(i)], order[j]);
      random_set[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])] = true;
    }
    const RadioResolution r = radio_resolution(restrict_to(pauses, keys, random_set), options.wifi);
    error.push_back(placement_error(r));
    resolution.push_back(coarseness(r));
    far.push_back(r.far_similar_share);
    near.push_back(r.near_similar_share);
  }
  if (resolution.empty()) return;
  const double m = median(resolution);
  if (std::isfinite(m)) step.random_resolution_m = m;
  step.random_error = median(error);
  step.random_far_similar_share = median(far);
  step.random_near_similar_share = median(near);
}

/// The unchosen candidate whose addition resolves best (lowest index among equals).
std::pair<int, RadioResolution> best_addition(const std::vector<PauseReadings>& pauses,
                                              const std::vector<slam::wifi::AccessPointKey>& keys,
                                              std::vector<bool>& chosen,
                                              const PlacementOptions& options) {
  int best = -1;
  RadioResolution best_r;
  for (std::size_t c = 0; c < chosen.size(); ++c) {
    if (chosen[c]) continue;
    chosen[c] = true;
    const RadioResolution r = radio_resolution(restrict_to(pauses, keys, chosen), options.wifi);
    chosen[c] = false;
    if (best < 0 || places_better(r, best_r)) {
      best = static_cast<int>(c);
      best_r = r;
    }
  }
  return {best, best_r};
}

}  // namespace

PlacementResult greedy_placement(const sim::scene::Scene& scene, const PlacementOptions& options) {
  const auto progress = [&](const std::string& line) {
    if (options.on_progress) options.on_progress(line);
  };
  PlacementResult result;

  // The scene's own placement, for reference, and the plan the candidates stand in.
  const auto site = std::make_shared<const sim::site::Site>(scene);
  const std::vector<PauseSample> own = simulate_pauses(site, options.wifi);
  result.scene_own = radio_resolution(own, options.wifi);
  for (const PauseSample& p : own) result.pause_positions_m.push_back(p.position_m);
  if (own.size() < 2) {
    throw InvalidInputError(fmt::format(
        "{}: the route has {} Wi-Fi pause(s) (route.pause): a placement needs at least two pauses "
        "to tell apart",
        scene.name, own.size()));
  }
  result.scene_access_points = static_cast<int>(site->access_points().size());
  const std::vector<Eigen::Vector2d> spots = candidate_spots(*site, options);
  result.plan = site->world().plan;
  result.level = site->world().level_id;  // candidates on the route's level, as its pauses
  for (const Eigen::Vector2d& s : spots)
    result.candidates.emplace_back(s.x(), s.y(), scene.access_points.height_m);
  progress(
      fmt::format("simulating the route's scans with {} candidate access points", spots.size()));
  std::vector<slam::wifi::AccessPointKey> keys;
  const std::vector<PauseReadings> pauses = simulate_candidates(*site, result, options, keys);

  // Greedy: add the candidate whose addition resolves best.
  std::vector<bool> chosen(spots.size(), false);
  const auto text = [](const std::optional<double>& v) {
    return v ? fmt::format("{:.1f} m", *v) : std::string("none");
  };
  for (int k = 1; k <= options.budget; ++k) {
    const auto [best, best_r] = best_addition(pauses, keys, chosen, options);
    chosen[static_cast<std::size_t>(best)] = true;
    PlacementStep step;
    step.count = k;
    step.candidate = best;
    step.greedy = best_r;
    step.greedy_error = placement_error(best_r);
    random_baseline(pauses, keys, k, options, step);
    progress(
        fmt::format("{:>3} APs: +({:.1f}, {:.1f}) error {:.3f}, resolution {} (random: {:.3f}, "
                    "{})",
                    k, spots[static_cast<std::size_t>(best)].x(),
                    spots[static_cast<std::size_t>(best)].y(), step.greedy_error,
                    text(best_r.resolution_m), step.random_error, text(step.random_resolution_m)));
    result.steps.push_back(step);
  }
  return result;
}

}  // namespace wifislam::study
