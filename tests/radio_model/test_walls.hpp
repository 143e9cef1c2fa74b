#pragma once
// Hand-built wall meshes for the radio tests: walls as closed boxes (thick walls) or as two
// facing rectangles (thin walls), each physical wall one wall_id on all its faces.

#include <array>
#include <cstdint>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "radio_model/wall_mesh.hpp"

namespace wifislam::test {

// A quad a-b-c-d (counter-clockwise seen from the side its normal points to) as two triangles.
inline void add_quad(radio_model::WallMesh& mesh, const Eigen::Vector3f& a,
                     const Eigen::Vector3f& b, const Eigen::Vector3f& c, const Eigen::Vector3f& d,
                     radio_model::WallMaterial material, int wall_id, bool slab = false) {
  const auto base = static_cast<std::uint32_t>(mesh.positions_m.size());
  for (const auto& p : {a, b, c, d}) mesh.positions_m.push_back(p);
  const Eigen::Vector3f normal = (b - a).cross(c - a).normalized();
  for (const std::array<std::uint32_t, 3>& v :
       {std::array<std::uint32_t, 3>{base, base + 1, base + 2},
        std::array<std::uint32_t, 3>{base, base + 2, base + 3}}) {
    radio_model::WallMesh::Face face;
    face.v = v;
    face.material = material;
    face.wall_id = wall_id;
    face.free_side = normal;
    face.slab = slab;
    mesh.faces.push_back(face);
  }
}

// An axis-aligned box [lo, hi] with all six faces carrying `wall_id`, normals pointing out of the
// box (toward free space, as the world's mesh has them).
inline void add_box(radio_model::WallMesh& mesh, const Eigen::Vector3f& lo,
                    const Eigen::Vector3f& hi, radio_model::WallMaterial material, int wall_id,
                    bool slab = false) {
  const float x0 = lo.x(), y0 = lo.y(), z0 = lo.z(), x1 = hi.x(), y1 = hi.y(), z1 = hi.z();
  using V = Eigen::Vector3f;
  add_quad(mesh, V(x0, y0, z0), V(x0, y0, z1), V(x0, y1, z1), V(x0, y1, z0), material, wall_id,
           slab);
  add_quad(mesh, V(x1, y0, z0), V(x1, y1, z0), V(x1, y1, z1), V(x1, y0, z1), material, wall_id,
           slab);
  add_quad(mesh, V(x0, y0, z0), V(x1, y0, z0), V(x1, y0, z1), V(x0, y0, z1), material, wall_id,
           slab);
  add_quad(mesh, V(x0, y1, z0), V(x0, y1, z1), V(x1, y1, z1), V(x1, y1, z0), material, wall_id,
           slab);
  add_quad(mesh, V(x0, y0, z0), V(x0, y1, z0), V(x1, y1, z0), V(x1, y0, z0), material, wall_id,
           slab);
  add_quad(mesh, V(x0, y0, z1), V(x1, y0, z1), V(x1, y1, z1), V(x0, y1, z1), material, wall_id,
           slab);
}

// A floor slab between storeys: the box x, y in [lo, hi] from z0 to z1, its faces slab faces.
inline void add_slab(radio_model::WallMesh& mesh, const Eigen::Vector2f& lo,
                     const Eigen::Vector2f& hi, float z0, float z1,
                     radio_model::WallMaterial material, int wall_id) {
  add_box(mesh, Eigen::Vector3f(lo.x(), lo.y(), z0), Eigen::Vector3f(hi.x(), hi.y(), z1), material,
          wall_id, true);
}

// A wall across the x axis at x = x0 (thickness t, y in [-half_len, half_len], height h),
// optionally with a door opening of `door_width` centred on y = 0 up to 2.1 m (lintel above).
// Returned as boxes sharing `wall_id`.
inline void add_wall_x(radio_model::WallMesh& mesh, float x0, float t, float half_len, float h,
                       radio_model::WallMaterial material, int wall_id, float door_width = 0.0f) {
  using V = Eigen::Vector3f;
  if (door_width <= 0.0f) {
    add_box(mesh, V(x0, -half_len, 0), V(x0 + t, half_len, h), material, wall_id);
    return;
  }
  const float d = 0.5f * door_width;
  add_box(mesh, V(x0, -half_len, 0), V(x0 + t, -d, h), material, wall_id);
  add_box(mesh, V(x0, d, 0), V(x0 + t, half_len, h), material, wall_id);
  add_box(mesh, V(x0, -d, 2.1f), V(x0 + t, d, h), material, wall_id);  // lintel
}

// A wall given as its two faces only (front and back, no end caps), as a wall's two plan faces
// extrude to when the end caps are left out.
inline void add_two_face_wall_x(radio_model::WallMesh& mesh, float x0, float t, float half_len,
                                float h, radio_model::WallMaterial material, int wall_id) {
  using V = Eigen::Vector3f;
  add_quad(mesh, V(x0, -half_len, 0), V(x0, -half_len, h), V(x0, half_len, h), V(x0, half_len, 0),
           material, wall_id);  // normal -x
  add_quad(mesh, V(x0 + t, -half_len, 0), V(x0 + t, half_len, 0), V(x0 + t, half_len, h),
           V(x0 + t, -half_len, h), material, wall_id);  // normal +x
}

}  // namespace wifislam::test
