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
sim::Scene imported_scene(const ImportedPlan& plan, const SceneOptions& options);

/// The scene file's text: a comment header (source, level, projection, notes, attribution),
/// then the resolved scene.
std::string imported_scene_yaml(const ImportedPlan& plan, const sim::Scene& scene,
                                const std::vector<std::string>& attribution_lines);

}  // namespace wifislam::floorplan
