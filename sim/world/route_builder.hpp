#pragma once
// Scene route -> smooth RoutePath through walkable space.

#include "sim/scene/scene.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::world {

/// The route's node sequence as a polyline whose corners are rounded by circular arcs of
/// `turn_radius_m` (smaller where the legs are too short for it; a full reversal at a dead end
/// turns on the spot), sampled at most every 0.05 m with cumulative arc length and heading. The
/// first and last points are the first and last nodes, unsmoothed (also for loops, which end where
/// they start).
///
/// Rejects (Scene::reject: located at `route.nodes[i]` in the scene file) a route where two
/// consecutive nodes are not joined by a corridor (naming both), or where a sample leaves walkable
/// space or comes closer than `min_wall_clearance_m` to a wall face (naming the leg, the position
/// and the clearance found). The clearance is the exact point-to-segment distance to every wall
/// face of the plan.
RoutePath build_route(const scene::Scene& scene, const FloorPlan& plan);

}  // namespace wifislam::sim::world
