#pragma once
// Ceiling lights: along every corridor's centre line every `appearance.light_spacing_m`, on a grid
// of that spacing over open areas, and one in the middle of every room.

#include <vector>

#include "sim/scene/scene.hpp"
#include "sim/world/plan_layout.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::world {

/// Needs plan.free_space, plan.rooms and plan.wall_height_m. Lights hang 1 cm below the ceiling,
/// lie in free space and are never closer than half a spacing to one another.
std::vector<CeilingLight> place_ceiling_lights(const scene::Scene& scene, const PlanLayout& layout,
                                               const FloorPlan& plan);

}  // namespace wifislam::sim::world
