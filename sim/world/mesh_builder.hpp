#pragma once
// FloorPlan -> triangle mesh.
//
// - Walls: every wall face extruded from the floor to `wall_height_m` (both faces of every wall,
//   outside faces included), plus caps on top and underneath, so each wall solid is a closed
//   surface: every edge of the kWall/kDoor/kWallTop triangles is shared by exactly two of them,
//   once in each direction. A closed door's leaf is the part of its two faces below the door
//   height (kDoor, kWoodDoor); above it the wall continues (the lintel).
// - Floor (z = 0, facing up) and ceiling (z = wall height, facing down) over all free space.
// - Door frames (kDoorFrame strips 3 mm proud of both faces around every door) and, over open
//   doors, a lintel (kDoorFrame; its own wall id, wall_count + door index, for the radio model).
// - Ceiling lights (kLight quads facing down), posters and landmarks (kPoster quads 4-6 mm off the
//   wall, see poster_layout.hpp).
// Normals point into free space (outside faces: away from the building); texture coordinates are
// in metres (walls: u along the wall, v up; floor, ceiling, caps, lights: x, y). Triangles whose
// area is below 1e-10 m2 (numerically flat slivers of non-axis-aligned caps) are left out.

#include "sim/scene/scene.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::world {

Mesh build_mesh(const scene::Scene& scene, const FloorPlan& plan);

}  // namespace wifislam::sim::world
