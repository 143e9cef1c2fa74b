#pragma once
// The levels of a scene (scene key `levels:`): which level each piece of the plan is on, where
// each level stands, and one level's part of a scene as a one-level scene that the world
// generator builds as it builds any other. A scene without `levels:` has one level, unnamed, at
// 0 m; everything here treats it as such, so one-level scenes take the path they always took.

#include <optional>
#include <string>
#include <vector>

#include "sim/scene/scene.hpp"

namespace wifislam::sim::scene {

/// A level as the world uses it: every default resolved.
struct ResolvedLevel {
  std::string id;  // empty for the one level of a scene without `levels:`
  double elevation_m = 0.0;
  double storey_height_m = 0.0;
  double slab_thickness_m = 0.0;
  WallMaterial slab_material = WallMaterial::kConcrete;
};

/// The scene's levels in file order, defaults resolved (scene.hpp, Level): one unnamed level at
/// 0 m for a scene without `levels:`.
std::vector<ResolvedLevel> resolved_levels(const Scene& scene);

/// Whether the scene has a `levels:` key (more than the implicit one level).
inline bool has_levels(const Scene& scene) { return !scene.levels.empty(); }

/// The level a piece names, with an empty name meaning the first level.
std::string level_or_first(const Scene& scene, const std::string& level);

/// The level the route runs on.
inline std::string route_level(const Scene& scene) {
  return level_or_first(scene, scene.route.level);
}

/// Index of the level `id` in scene.levels, or -1.
int level_index(const Scene& scene, const std::string& id);

/// Throws InvalidInputError naming `option` when `level` is set and the scene has no such level
/// (a command's --level, checked before any work).
void require_level(const Scene& scene, const std::string& level, const std::string& option);

/// Throws InvalidInputError naming `option` when a receiver height given on the command line is
/// not between the floor and the ceiling (building.wall_height_m); an unset height passes.
void require_height_under_ceiling(const Scene& scene, std::optional<double> height_m,
                                  const std::string& option);

/// The part of a scene on level `level_id`: its nodes, corridors, open areas, spaces, doors,
/// obstacles and listed access points, with `levels` cleared and everything else (building,
/// appearance, route, sensors, radio) as in the scene. List items are renumbered; the key
/// locations follow them and key_paths_in_file maps each new item back to the file's, so
/// Scene::reject on the part names the file's line and key. A scene without `levels:` is
/// returned whole.
Scene scene_on_level(const Scene& scene, const std::string& level_id);

}  // namespace wifislam::sim::scene
