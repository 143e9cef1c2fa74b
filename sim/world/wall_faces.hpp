#pragma once
// Wall faces of the floor plan: the boundary edges of the wall solids, split into the pieces the
// radio model and the renderer need.
//
// 1. Every boundary edge of a wall solid becomes a face with the wall on its right.
// 2. Faces on the two sides of a closed door's opening are cut at the door's edges; the pieces in
//    the opening are the door leaf (material kWoodDoor).
// 3. Faces facing each other across one wall (antiparallel, at most two wall thicknesses apart)
//    are cut at each other's ends, then each such pair shares one `wall_id`: a physical wall is a
//    straight piece of wall with its two faces, so a ray through it is counted once. A wall solid
//    that is one convex block (a pillar) is one wall.
// 4. Material by what the wall bounds: room walls take the room row's material, other corridor
//    walls the corridor's, open areas their own; door leaves are kWoodDoor.
// 5. Faces toward free space are cut into appearance segments of at most
//    `appearance.segment_length_m`; each segment uses the shared look (variant 0) with probability
//    `aliasing`, else a unique variant, drawn from Rng::stream(seed, "appearance/segments").
//    Outside faces (exterior = true) get no segment.

#include "sim/scene/scene.hpp"
#include "sim/world/plan_layout.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::world {

/// Fills plan.wall_faces, plan.appearance_segments and plan.wall_count from plan.walls,
/// plan.free_space, plan.rooms and plan.doors.
void build_wall_faces(const scene::Scene& scene, const PlanLayout& layout, FloorPlan& plan);

}  // namespace wifislam::sim::world
