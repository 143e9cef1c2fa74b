#pragma once
// The world's walls as the radio model takes them (radio_model/wall_mesh.hpp): every mesh triangle
// that bounds a physical wall (wall_id >= 0: wall faces, closed door leaves, jambs, lintels), with
// its material and the mesh's normal at its first vertex as the free-space side. The vertex
// buffer is the mesh's own, whole, so the radio model's Embree scene is built from the same
// vertices the renderer draws.
//
// A building of several levels: every storey's walls at its elevation, closed at their tops (a
// link between storeys can leave a wall through its top), wall ids renumbered so that no two
// storeys share one, and under every storey but the lowest its floor slab, a closed
// box over the storey's plan bounds from elevation - slab thickness to the elevation, of the
// level's slab material. The slab's six faces share one wall id, so a link through it crosses
// one floor (the counting rule of radio_model/embree_wall_scene.hpp).

#include "radio_model/wall_mesh.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::world {

radio_model::WallMesh radio_wall_mesh(const Mesh& mesh);

/// The whole building's walls: radio_wall_mesh(world.mesh) for a one-level world, else every
/// storey's walls and the slabs between them, in the building's frame.
radio_model::WallMesh radio_wall_mesh(const World& world);

/// The building's extent in (x, y): the route level's plan bounds, or every storey's together.
void building_bounds(const World& world, Eigen::Vector2d& min_m, Eigen::Vector2d& max_m);

}  // namespace wifislam::sim::world
