#include "sim/scene/scene_levels.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"

namespace wifislam::sim::scene {

std::vector<ResolvedLevel> resolved_levels(const Scene& scene) {
  if (scene.levels.empty()) {
    return {ResolvedLevel{"", 0.0, scene.building.wall_height_m, 0.0, WallMaterial::kConcrete}};
  }
  std::vector<ResolvedLevel> out;
  for (std::size_t i = 0; i < scene.levels.size(); ++i) {
    const Level& level = scene.levels[i];
    ResolvedLevel r;
    r.id = level.id;
    r.slab_thickness_m = level.slab_thickness_m;
    r.slab_material = level.slab_material;
    // Walls reach the slab above: the next level's in the file, else one like its own.
    const double slab_above_m =
        i + 1 < scene.levels.size() ? scene.levels[i + 1].slab_thickness_m : level.slab_thickness_m;
    // Defaults are sums of decimals: rounded to the micrometre, so 2.8 + 0.3 is written 3.1.
    const auto micrometres = [](double m) { return std::round(m * 1e6) / 1e6; };
    r.storey_height_m =
        level.storey_height_m.value_or(micrometres(scene.building.wall_height_m + slab_above_m));
    r.elevation_m = level.elevation_m.value_or(
        out.empty() ? 0.0 : micrometres(out.back().elevation_m + out.back().storey_height_m));
    out.push_back(r);
  }
  return out;
}

std::string level_or_first(const Scene& scene, const std::string& level) {
  if (!level.empty() || scene.levels.empty()) return level;
  return scene.levels.front().id;
}

int level_index(const Scene& scene, const std::string& id) {
  for (std::size_t i = 0; i < scene.levels.size(); ++i)
    if (scene.levels[i].id == id) return static_cast<int>(i);
  return -1;
}

void require_level(const Scene& scene, const std::string& level, const std::string& option) {
  if (level.empty() || level_index(scene, level) >= 0) return;
  if (scene.levels.empty()) {
    throw InvalidInputError(
        fmt::format("{} {}: the scene has one level (no `levels:` key)", option, level));
  }
  std::string ids;
  for (const Level& l : scene.levels) ids += (ids.empty() ? "" : ", ") + l.id;
  throw InvalidInputError(
      fmt::format("{} {}: the scene has no such level (levels: {})", option, level, ids));
}

void require_height_under_ceiling(const Scene& scene, std::optional<double> height_m,
                                  const std::string& option) {
  const double ceiling_m = scene.building.wall_height_m;
  if (height_m && !(*height_m > 0.0 && *height_m < ceiling_m)) {
    throw InvalidInputError(
        fmt::format("{}: {} m is not between the floor and the ceiling (0 to {} m, the scene's "
                    "building.wall_height_m)",
                    option, *height_m, ceiling_m));
  }
}

namespace {

/// Keeps the items of `list` (key `name`) on `level_id`, renumbered, with their key locations.
template <class T, class LevelOf>
std::vector<T> keep_on_level(const Scene& scene, const std::vector<T>& list,
                             const std::string& name, const std::string& level_id, LevelOf level_of,
                             Scene& part) {
  std::vector<T> kept;
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (level_of(list[i]) != level_id) continue;
    const std::string old_key = fmt::format("{}[{}]", name, i);
    const std::string new_key = fmt::format("{}[{}]", name, kept.size());
    kept.push_back(list[i]);
    part.key_paths_in_file[new_key] = old_key;
    // The item's own key and every key under it ("spaces[7]", "spaces[7].polygon_m[2]").
    for (auto it = scene.key_locations.lower_bound(old_key);
         it != scene.key_locations.end() && it->first.compare(0, old_key.size(), old_key) == 0;
         ++it) {
      const std::string rest = it->first.substr(old_key.size());
      if (!rest.empty() && rest[0] != '.' && rest[0] != '[') continue;  // "spaces[70]"
      part.key_locations[new_key + rest] = it->second;
    }
  }
  return kept;
}

bool is_list_item_key(const std::string& key) {
  for (const char* list : {"nodes[", "corridors[", "open_areas[", "spaces[", "doors[", "obstacles[",
                           "access_points.list["}) {
    if (key.rfind(list, 0) == 0) return true;
  }
  return false;
}

}  // namespace

Scene scene_on_level(const Scene& scene, const std::string& level_id) {
  if (scene.levels.empty()) return scene;
  Scene part = scene;
  part.levels.clear();
  part.key_locations.clear();
  part.key_paths_in_file.clear();
  for (const auto& [key, where] : scene.key_locations)
    if (!is_list_item_key(key)) part.key_locations[key] = where;
  const auto on = [&](const std::string& level) { return level_or_first(scene, level); };
  part.nodes = keep_on_level(
      scene, scene.nodes, "nodes", level_id, [&](const SceneNode& n) { return on(n.level); }, part);
  // A corridor is on its nodes' level (validation checks that both ends agree).
  part.corridors = keep_on_level(
      scene, scene.corridors, "corridors", level_id,
      [&](const Corridor& c) {
        const SceneNode* from = scene.find_node(c.from);
        return from ? on(from->level) : std::string();
      },
      part);
  part.open_areas = keep_on_level(
      scene, scene.open_areas, "open_areas", level_id,
      [&](const OpenArea& a) { return on(a.level); }, part);
  part.spaces = keep_on_level(
      scene, scene.spaces, "spaces", level_id, [&](const Space& s) { return on(s.level); }, part);
  part.doors = keep_on_level(
      scene, scene.doors, "doors", level_id, [&](const SpaceDoor& d) { return on(d.level); }, part);
  part.obstacles = keep_on_level(
      scene, scene.obstacles, "obstacles", level_id, [&](const Obstacle& o) { return on(o.level); },
      part);
  part.access_points.explicit_list = keep_on_level(
      scene, scene.access_points.explicit_list, "access_points.list", level_id,
      [&](const AccessPointSpec& a) { return on(a.level); }, part);
  if (part.access_points.placement == ApPlacement::kExplicit)
    part.access_points.count = static_cast<int>(part.access_points.explicit_list.size());
  return part;
}

}  // namespace wifislam::sim::scene
