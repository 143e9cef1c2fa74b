#include "sim/site/ap_changes.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "sim/scene/scene_levels.hpp"
#include "sim/site/ap_placement.hpp"
#include "sim/world/radio_wall_mesh.hpp"

namespace wifislam::sim::site {

namespace {

/// The elevation of the level a new AP names (0 for a one-level building).
double new_ap_elevation_m(const scene::Scene& scene, const world::World& world,
                          const scene::AccessPointChange& c, const std::string& key) {
  if (world.storeys.empty()) {
    if (!c.level.empty()) scene.reject(key + ".level", "the scene has no levels");
    return 0.0;
  }
  const std::string id = scene::level_or_first(scene, c.level);
  for (const world::Storey& storey : world.storeys)
    if (storey.level_id == id) return storey.elevation_m;
  scene.reject(key + ".level", fmt::format("no level '{}' in the scene", c.level));
}

}  // namespace

std::vector<radio_model::AccessPoint> apply_access_point_changes(
    std::vector<radio_model::AccessPoint> aps, const scene::Scene& scene,
    const world::World& world) {
  const auto& changes = scene.access_points.changes;
  if (changes.empty()) return aps;
  const int session = scene::session_of(scene);
  Eigen::Vector2d min_m, max_m;
  world::building_bounds(world, min_m, max_m);
  const std::uint64_t seed = access_point_seed(scene);
  radio_model::MacAllocator macs(seed);
  for (const radio_model::AccessPoint& ap : aps) macs.reserve(ap.base_mac());
  const int placed = static_cast<int>(aps.size());
  int new_index = 0;
  for (std::size_t i = 0; i < changes.size(); ++i) {
    const scene::AccessPointChange& c = changes[i];
    const std::string key = fmt::format("access_points.changes[{}]", i);
    const bool is_new = c.change == scene::AccessPointChangeKind::kNew;
    const int new_id = placed + (is_new ? new_index++ : 0);
    // Checked in every session, so a bad change fails the session-0 run as well.
    if (is_new == c.ap.has_value())
      scene.reject(key + (is_new ? ".ap" : ""),
                   is_new ? "a new access point takes no `ap` (its id follows the others)"
                          : fmt::format("`{}` needs `ap`, the id of the access point it changes",
                                        to_string(c.change)));
    const bool placed_somewhere = c.change == scene::AccessPointChangeKind::kMoved ||
                                  c.change == scene::AccessPointChangeKind::kNew;
    if (placed_somewhere != c.position_m.has_value())
      scene.reject(key + (placed_somewhere ? "" : ".position_m"),
                   placed_somewhere
                       ? fmt::format("`{}` needs `position_m`", to_string(c.change))
                       : fmt::format("`{}` takes no `position_m`", to_string(c.change)));
    if (c.position_m) {
      const Eigen::Vector2d xy = c.position_m->head<2>();
      if ((xy.array() < min_m.array()).any() || (xy.array() > max_m.array()).any())
        scene.reject(key + ".position_m",
                     fmt::format("({:.2f}, {:.2f}) m is outside the building, which spans "
                                 "({:.2f}, {:.2f}) to ({:.2f}, {:.2f}) m",
                                 xy.x(), xy.y(), min_m.x(), min_m.y(), max_m.x(), max_m.y()));
    }
    if (c.ap && static_cast<int>(*c.ap) >= placed + new_index)
      scene.reject(key + ".ap",
                   fmt::format("no access point {} (ids 0 to {}{})", *c.ap, placed + new_index - 1,
                               new_index > 0 ? ", new ones included" : ""));
    if (c.session > session) continue;
    if (is_new) {
      Eigen::Vector3d at = *c.position_m;
      at.z() += new_ap_elevation_m(scene, world, c, key);
      aps.push_back(radio_model::make_access_point(
          new_id, at, c.tx_power_dbm.value_or(scene.access_points.tx_power_dbm),
          scene.access_points.ssids_per_radio, seed, macs));
      continue;
    }
    const auto it = std::find_if(aps.begin(), aps.end(), [&](const radio_model::AccessPoint& a) {
      return a.id == static_cast<int>(*c.ap);
    });
    if (it == aps.end())
      scene.reject(key + ".ap",
                   fmt::format("access point {} is off from an earlier change by session {}", *c.ap,
                               c.session));
    switch (c.change) {
      case scene::AccessPointChangeKind::kOff:
        aps.erase(it);
        break;
      case scene::AccessPointChangeKind::kMoved: {
        // Moved within its level: z above the floor of the storey it stands on (the highest
        // at or below it; storeys are lowest first, and a basement's elevation is negative).
        double floor_m = world.storeys.empty() ? 0.0 : world.storeys.front().elevation_m;
        for (const world::Storey& storey : world.storeys)
          if (storey.elevation_m <= it->position_m.z())
            floor_m = std::max(floor_m, storey.elevation_m);
        it->position_m = {c.position_m->x(), c.position_m->y(), floor_m + c.position_m->z()};
        break;
      }
      case scene::AccessPointChangeKind::kPower:
        it->tx_power_dbm = std::clamp(it->tx_power_dbm + c.tx_power_step_db,
                                      radio_model::kMinTxPowerDbm, radio_model::kMaxTxPowerDbm);
        break;
      case scene::AccessPointChangeKind::kNew:
        break;
    }
  }
  return aps;
}

}  // namespace wifislam::sim::site
