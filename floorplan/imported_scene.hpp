#pragma once
// An imported plan level -> a scene file our loader reads unchanged: spaces, doors, obstacles,
// a planned route (route_planner.hpp) and defaults for what a plan does not say (wall height,
// access points, sensors). The header comment carries the source, the projection and the
// data's attribution, which must travel with every derivative.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "floorplan/imported_plan.hpp"
#include "sim/scene/scene.hpp"

namespace wifislam::floorplan {

struct SceneOptions {
  std::string name;                      // default: from the file name and level
  std::vector<Eigen::Vector2d> route_m;  // user waypoints (local metres), visited in order
  int laps = 2;
  std::optional<int> access_points;  // default: one per 100 m^2 of free space, at least 4
  std::uint64_t seed = 1;
  double wall_height_m = 2.8;
};

/// The scene, with its route planned through the plan's walkable space and checked by the same
/// route builder `generate` uses. Throws InvalidInputError when no route fits.
sim::scene::Scene imported_scene(const ImportedPlan& plan, const SceneOptions& options);

/// Storeys of an imported building stand this far apart when the plan gives no heights (none of
/// the shipped formats does): the scene's wall height plus a 0.3 m slab, written into the scene.
inline constexpr double kImportedSlabThicknessM = 0.3;

/// A whole building: every level of `levels` (one import per level, all in one frame), each with
/// its spaces, doors and obstacles tagged with its level, stacked kImportedSlabThicknessM + wall
/// height apart in the order given (lowest first), concrete slabs between them. The route is
/// planned on `route_level` as imported_scene plans it; the access points are placed by rooms on
/// every level, `options.access_points` each (default: one per 100 m^2 of the route level's free
/// space, at least 4). Space ids are prefixed with their level ("<level>/<id>") to stay unique.
sim::scene::Scene imported_building_scene(const std::vector<ImportedPlan>& levels,
                                          const std::string& route_level,
                                          const SceneOptions& options);

/// The scene file's text: a comment header (source, level, projection, notes, attribution),
/// then the resolved scene.
std::string imported_scene_yaml(const ImportedPlan& plan, const sim::scene::Scene& scene,
                                const std::vector<std::string>& attribution_lines);

}  // namespace wifislam::floorplan
