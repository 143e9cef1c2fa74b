#include "sim/site/ap_placement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "sim/scene/scene_levels.hpp"
#include "sim/site/ap_changes.hpp"
#include "sim/world/plan_queries.hpp"
#include "sim/world/wall_face_grid.hpp"

namespace wifislam::sim::site {

namespace {

// Candidate spots: a 0.5 m lattice, 0.4 m off the wall faces. A plan too narrow for that (a
// corridor of the schema's smallest width, 0.8 m, has no lattice row 0.4 m from both walls)
// takes spots from a 0.1 m lattice 0.1 m off the walls, which any corridor of 0.8 m holds
// whatever its direction; the ray casts only need the AP off the wall faces.
struct Lattice {
  double spacing_m, clearance_m;
};
constexpr Lattice kLattice{0.5, 0.4};
constexpr Lattice kNarrowLattice{0.1, 0.1};
constexpr double kClearanceM = kLattice.clearance_m;

// Free-space spots on a lattice over the plan bounds, optionally restricted to one polygon.
std::vector<Eigen::Vector2d> candidate_spots(const world::FloorPlan& plan,
                                             const world::WallFaceGrid& walls,
                                             const world::Polygon2* inside,
                                             const Lattice& lattice = kLattice) {
  const double spacing_m = lattice.spacing_m;
  std::vector<Eigen::Vector2d> spots;
  Eigen::Vector2d lo = plan.bounds_min_m, hi = plan.bounds_max_m;
  if (inside) {
    lo = hi = inside->front();
    for (const auto& v : *inside) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
  }
  const double x0 = std::floor(lo.x() / spacing_m) * spacing_m + 0.5 * spacing_m;
  const double y0 = std::floor(lo.y() / spacing_m) * spacing_m + 0.5 * spacing_m;
  std::vector<double> crossings;
  std::vector<std::pair<double, double>> spans;
  for (double y = y0; y < hi.y(); y += spacing_m) {
    // The row's spans inside some free-space outer ring, by ring_contains's own crossing rule
    // (inside iff an odd number of crossings lies right of x): a spot outside every span fails
    // regions_contain, so only spots within spans are tested. A big sparse plan (a 10 km L) then
    // costs a test per free spot, not per lattice point of its bounding box.
    spans.clear();
    for (const world::PolygonWithHoles2& region : plan.free_space) {
      const world::Polygon2& ring = region.outer;
      crossings.clear();
      for (std::size_t i = 0, n = ring.size(), j = n - 1; i < n; j = i++) {
        const Eigen::Vector2d& a = ring[i];
        const Eigen::Vector2d& b = ring[j];
        if ((a.y() > y) != (b.y() > y)) {
          crossings.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
        }
      }
      std::sort(crossings.begin(), crossings.end());
      for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
        spans.emplace_back(crossings[k], crossings[k + 1]);
      }
    }
    std::sort(spans.begin(), spans.end());
    std::size_t span = 0;
    double span_end = spans.empty() ? 0.0 : spans[0].second;
    // x is computed afresh from k (never accumulated), so these are the lattice's x values
    // whether stepped through or jumped to.
    for (std::int64_t k = 0;; ++k) {
      const double x = x0 + static_cast<double>(k) * spacing_m;
      if (!(x < hi.x())) break;
      // Spans are half-open, [start, end); overlapping ones are merged as they are passed.
      while (span < spans.size() && x >= span_end) {
        if (++span < spans.size()) span_end = std::max(span_end, spans[span].second);
      }
      if (span == spans.size()) break;
      if (x < spans[span].first) {
        const auto next =
            static_cast<std::int64_t>(std::ceil((spans[span].first - x0) / spacing_m));
        if (next > k + 1) k = next - 1;  // continue at the span's first lattice x
        continue;
      }
      const Eigen::Vector2d p(x, y);
      if (inside && !world::ring_contains(*inside, p)) continue;
      if (!world::regions_contain(plan.free_space, p)) continue;
      if (walls.nearest_within_m(p, lattice.clearance_m) < lattice.clearance_m) continue;
      spots.push_back(p);
    }
  }
  return spots;
}

void shuffle(std::vector<Eigen::Vector2d>& v, Rng& rng) {
  for (std::size_t i = v.size(); i > 1; --i) {
    const auto j = static_cast<std::size_t>(rng.uniform_int(0, static_cast<std::int64_t>(i) - 1));
    std::swap(v[i - 1], v[j]);
  }
}

bool far_enough(const std::vector<Eigen::Vector2d>& chosen, const Eigen::Vector2d& p,
                double spacing) {
  return std::all_of(chosen.begin(), chosen.end(),
                     [&](const Eigen::Vector2d& q) { return (q - p).norm() >= spacing; });
}

// Takes up to `want` spots from `pool` (already shuffled) keeping `spacing` from every chosen
// spot; halves the spacing when the pool runs out, so a crowded request still succeeds.
void take_spaced(const std::vector<Eigen::Vector2d>& pool, int want, double spacing,
                 std::vector<Eigen::Vector2d>& chosen) {
  int taken = 0;
  for (double s = spacing; taken < want; s *= 0.5) {
    for (const auto& p : pool) {
      if (taken >= want) break;
      if (far_enough(chosen, p, s)) {
        chosen.push_back(p);
        ++taken;
      }
    }
    if (s < 1e-3) break;
  }
}

std::vector<Eigen::Vector3d> at_height(const std::vector<Eigen::Vector2d>& xy, double height_m) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& p : xy) out.emplace_back(p.x(), p.y(), height_m);
  return out;
}

/// kColinear: `count` points evenly from line_from_m to line_to_m (one point: the middle).
std::vector<Eigen::Vector2d> colinear_spots(const scene::AccessPoints& spec) {
  const Eigen::Vector2d a = spec.line_from_m, b = spec.line_to_m;
  if ((b - a).norm() < 1e-9 && spec.count > 1)
    throw InvalidInputError("colinear placement needs line_from_m and line_to_m to differ");
  std::vector<Eigen::Vector2d> xy;
  for (int i = 0; i < spec.count; ++i) {
    const double t = spec.count == 1 ? 0.5 : static_cast<double>(i) / (spec.count - 1);
    xy.push_back(a + t * (b - a));
  }
  return xy;
}

/// Candidate spots of the whole plan: the usual lattice, or the narrow one when the usual has
/// none.
std::vector<Eigen::Vector2d> lattice_spots(const world::FloorPlan& plan,
                                           const world::WallFaceGrid& walls) {
  std::vector<Eigen::Vector2d> spots = candidate_spots(plan, walls, nullptr);
  if (spots.empty()) spots = candidate_spots(plan, walls, nullptr, kNarrowLattice);
  return spots;
}

/// kGrid: a cols x rows grid over the plan bounds, shaped like them; each grid point takes the
/// nearest free spot not taken yet.
std::vector<Eigen::Vector2d> grid_spots(const scene::AccessPoints& spec,
                                        const world::FloorPlan& plan,
                                        const std::vector<Eigen::Vector2d>& free_spots) {
  std::vector<Eigen::Vector2d> chosen;
  const Eigen::Vector2d extent = plan.bounds_max_m - plan.bounds_min_m;
  const double aspect = extent.y() > 0 ? extent.x() / extent.y() : 1.0;
  const int cols = std::max(1, static_cast<int>(std::lround(std::sqrt(spec.count * aspect))));
  const int rows = (spec.count + cols - 1) / cols;
  std::vector<bool> used(free_spots.size(), false);
  for (int i = 0; i < spec.count; ++i) {
    const int r = i / cols, c = i % cols;
    const Eigen::Vector2d ideal =
        plan.bounds_min_m +
        Eigen::Vector2d((c + 0.5) * extent.x() / cols, (r + 0.5) * extent.y() / rows);
    std::size_t best = free_spots.size();
    double best_d = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < free_spots.size(); ++k) {
      const double d = (free_spots[k] - ideal).squaredNorm();
      if (!used[k] && d < best_d) {
        best_d = d;
        best = k;
      }
    }
    if (best == free_spots.size())
      throw InvalidInputError(fmt::format(
          "the floor plan has room for only {} grid positions of the {} asked for", i, spec.count));
    used[best] = true;
    chosen.push_back(free_spots[best]);
  }
  return chosen;
}

/// The room indices in a random order (a Fisher-Yates shuffle drawn from `rng`).
std::vector<std::size_t> shuffled_rooms(const world::FloorPlan& plan, Rng& rng) {
  std::vector<std::size_t> order(plan.rooms.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  for (std::size_t i = order.size(); i > 1; --i)
    std::swap(
        order[i - 1],
        order[static_cast<std::size_t>(rng.uniform_int(0, static_cast<std::int64_t>(i) - 1))]);
  return order;
}

/// kRooms: all but a quarter (rounded down) of the access points in rooms, at most one per room,
/// rooms in random order; the rest (and whatever the rooms could not take) in corridors and halls.
std::vector<Eigen::Vector2d> room_spots(const scene::AccessPoints& spec,
                                        const world::FloorPlan& plan,
                                        const world::WallFaceGrid& walls,
                                        const std::vector<Eigen::Vector2d>& free_spots, Rng& rng) {
  std::vector<Eigen::Vector2d> chosen;
  const int in_rooms_wanted = spec.count - spec.count / 4;
  for (std::size_t room : shuffled_rooms(plan, rng)) {
    if (static_cast<int>(chosen.size()) >= in_rooms_wanted) break;
    auto spots = candidate_spots(plan, walls, &plan.rooms[room].polygon_m);
    shuffle(spots, rng);
    for (const auto& p : spots) {
      if (far_enough(chosen, p, spec.min_spacing_m)) {
        chosen.push_back(p);
        break;
      }
    }
  }
  std::vector<Eigen::Vector2d> walkable;
  for (const auto& p : free_spots)
    if (world::regions_contain(plan.walkable, p)) walkable.push_back(p);
  if (walkable.empty()) walkable = free_spots;
  shuffle(walkable, rng);
  take_spaced(walkable, spec.count - static_cast<int>(chosen.size()), spec.min_spacing_m, chosen);
  return chosen;
}

/// kGrid, kRandom and kRooms: spots picked from the plan's free lattice spots.
std::vector<Eigen::Vector2d> spots_from_lattice(const scene::AccessPoints& spec,
                                                const world::FloorPlan& plan, std::uint64_t seed) {
  Rng rng = Rng::stream(seed, fmt::format("access_points/placement/{}", to_string(spec.placement)));
  const world::WallFaceGrid walls(plan, kClearanceM);
  std::vector<Eigen::Vector2d> free_spots = lattice_spots(plan, walls);
  if (free_spots.empty())
    throw InvalidInputError(fmt::format(
        "no spot of the floor plan is {} m from the walls to hold an access point (placement "
        "'{}'); give their positions with placement: explicit",
        kNarrowLattice.clearance_m, to_string(spec.placement)));
  std::vector<Eigen::Vector2d> chosen;
  switch (spec.placement) {
    case scene::ApPlacement::kGrid:
      chosen = grid_spots(spec, plan, free_spots);
      break;
    case scene::ApPlacement::kRandom:
      shuffle(free_spots, rng);
      take_spaced(free_spots, spec.count, spec.min_spacing_m, chosen);
      break;
    case scene::ApPlacement::kRooms:
      chosen = room_spots(spec, plan, walls, free_spots, rng);
      break;
    case scene::ApPlacement::kExplicit:
    case scene::ApPlacement::kColinear:
      break;
  }
  if (static_cast<int>(chosen.size()) < spec.count)
    throw InvalidInputError(fmt::format("only {} of {} access points fit in the floor plan",
                                        chosen.size(), spec.count));
  return chosen;
}

}  // namespace

std::uint64_t access_point_seed(const scene::Scene& scene) {
  return scene.access_points.seed.value_or(scene.seed);
}

std::vector<Eigen::Vector3d> place_access_point_positions(const scene::AccessPoints& spec,
                                                          const world::FloorPlan& plan,
                                                          std::uint64_t seed) {
  if (spec.placement == scene::ApPlacement::kExplicit) {
    std::vector<Eigen::Vector3d> out;
    for (const auto& e : spec.explicit_list) out.push_back(e.position_m);
    return out;
  }
  if (spec.count < 0)
    throw InvalidInputError(fmt::format("access_points.count must be >= 0 (got {})", spec.count));
  if (spec.count == 0) return {};
  if (spec.placement == scene::ApPlacement::kColinear)
    return at_height(colinear_spots(spec), spec.height_m);
  return at_height(spots_from_lattice(spec, plan, seed), spec.height_m);
}

std::vector<Eigen::Vector2d> access_point_candidate_spots(const world::FloorPlan& plan,
                                                          double spacing_m) {
  const world::WallFaceGrid walls(plan, kClearanceM);
  const std::vector<Eigen::Vector2d> spots = lattice_spots(plan, walls);
  std::vector<Eigen::Vector2d> kept;
  for (const Eigen::Vector2d& p : spots)
    if (far_enough(kept, p, spacing_m)) kept.push_back(p);
  return kept;
}

std::vector<radio_model::AccessPoint> make_access_points(const scene::Scene& scene,
                                                         const world::FloorPlan& plan) {
  const scene::AccessPoints& spec = scene.access_points;
  const std::uint64_t seed = access_point_seed(scene);
  std::vector<Eigen::Vector3d> positions;
  try {
    positions = place_access_point_positions(spec, plan, seed);
  } catch (const InvalidInputError& e) {
    scene.reject("access_points", e.what());  // located at the scene's access_points
  }
  radio_model::MacAllocator macs(seed);
  std::vector<radio_model::AccessPoint> aps;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    double tx = spec.tx_power_dbm;
    if (spec.placement == scene::ApPlacement::kExplicit && spec.explicit_list[i].tx_power_dbm)
      tx = *spec.explicit_list[i].tx_power_dbm;
    aps.push_back(radio_model::make_access_point(static_cast<int>(i), positions[i], tx,
                                                 spec.ssids_per_radio, seed, macs));
  }
  return aps;
}

std::vector<radio_model::AccessPoint> make_access_points(const scene::Scene& scene,
                                                         const world::World& world) {
  return apply_access_point_changes(placed_access_points(scene, world), scene, world);
}

std::vector<radio_model::AccessPoint> placed_access_points(const scene::Scene& scene,
                                                           const world::World& world) {
  if (world.storeys.empty()) return make_access_points(scene, world.plan);
  const std::uint64_t seed = access_point_seed(scene);
  radio_model::MacAllocator macs(seed);
  std::vector<radio_model::AccessPoint> aps;
  for (std::size_t k = 0; k < world.storeys.size(); ++k) {
    const world::Storey& storey = world.storeys[k];
    const scene::Scene part = scene::scene_on_level(scene, storey.level_id);
    const scene::AccessPoints& spec = part.access_points;
    // The lowest storey places from the scene's seed, as a one-level building does; every other
    // from a stream of its own, so adding a level moves no AP of another.
    const std::uint64_t level_seed =
        k == 0 ? seed : Rng::stream(seed, "access_points/level/" + storey.level_id).next_u64();
    std::vector<Eigen::Vector3d> positions;
    try {
      positions = place_access_point_positions(spec, storey.plan, level_seed);
    } catch (const InvalidInputError& e) {
      part.reject("access_points", fmt::format("level '{}': {}", storey.level_id, e.what()));
    }
    for (std::size_t i = 0; i < positions.size(); ++i) {
      double tx = spec.tx_power_dbm;
      if (spec.placement == scene::ApPlacement::kExplicit && spec.explicit_list[i].tx_power_dbm)
        tx = *spec.explicit_list[i].tx_power_dbm;
      Eigen::Vector3d at = positions[i];
      at.z() += storey.elevation_m;  // heights are above the level's floor
      aps.push_back(radio_model::make_access_point(static_cast<int>(aps.size()), at, tx,
                                                   spec.ssids_per_radio, seed, macs));
    }
  }
  return aps;
}

}  // namespace wifislam::sim::site
