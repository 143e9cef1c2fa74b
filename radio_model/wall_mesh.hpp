#pragma once
// The geometry the radio model is handed: the faces that bound wall and floor-slab material, as a
// triangle mesh.
// The simulator's world builds it from its mesh (sim/world/radio_wall_mesh.hpp); a test or
// another tool can build one by hand. Nothing else of the world reaches the radio model.

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "radio_model/wall_material.hpp"

namespace wifislam::radio_model {

struct WallMesh {
  struct Face {
    std::array<std::uint32_t, 3> v{};  // indices into positions_m
    int wall_id = 0;                   // the physical wall the face bounds (>= 0)
    WallMaterial material = WallMaterial::kPlasterboard;
    /// A direction pointing to free space on the face's side (the mesh's shading normal), or
    /// zero when unknown: then the winding alone (counter-clockwise seen from free space) says
    /// on which side the material lies.
    Eigen::Vector3f free_side = Eigen::Vector3f::Zero();
    /// A face of a floor slab between storeys rather than of a wall: a link through it crosses a
    /// floor, which the path loss models charge as a floor (propagation_model.hpp).
    bool slab = false;
  };
  std::vector<Eigen::Vector3f> positions_m;
  std::vector<Face> faces;
};

}  // namespace wifislam::radio_model
