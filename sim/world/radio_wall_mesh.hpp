#pragma once
// The world's walls as the radio model takes them (radio_model/wall_mesh.hpp): every mesh triangle
// that bounds a physical wall (wall_id >= 0: wall faces, closed door leaves, jambs, lintels), with
// its material and the mesh's normal at its first vertex as the free-space side. The vertex
// buffer is the mesh's own, whole, so the radio model's Embree scene is built from the same
// vertices the renderer draws.

#include "radio_model/wall_mesh.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim {

radio_model::WallMesh radio_wall_mesh(const Mesh& mesh);

}  // namespace wifislam::sim
