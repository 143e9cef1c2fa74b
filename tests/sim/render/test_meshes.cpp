#include "tests/sim/render/test_meshes.hpp"

#include <array>

#include <Eigen/Geometry>

namespace wifislam::test {

void add_quad(sim::world::Mesh& mesh, const Eigen::Vector3f& corner, const Eigen::Vector3f& along,
              const Eigen::Vector3f& up, const QuadLook& look) {
  const auto base = static_cast<std::uint32_t>(mesh.positions_m.size());
  const Eigen::Vector3f normal = along.cross(up).normalized();
  const float w = along.norm(), h = up.norm();
  const Eigen::Vector3f corners[4] = {corner, corner + along, corner + along + up, corner + up};
  const Eigen::Vector2f uvs[4] = {{0, 0}, {w, 0}, {w, h}, {0, h}};
  for (int i = 0; i < 4; ++i) {
    mesh.positions_m.push_back(corners[i]);
    mesh.normals.push_back(normal);
    mesh.uv_m.push_back(look.uv_origin_m + uvs[i]);
  }
  for (const auto& tri :
       {std::array<std::uint32_t, 3>{0, 1, 2}, std::array<std::uint32_t, 3>{0, 2, 3}}) {
    sim::world::Triangle t;
    for (int k = 0; k < 3; ++k) t.v[k] = base + tri[k];
    t.surface = look.surface;
    t.appearance_variant = look.variant;
    t.decoration = look.decoration;
    mesh.triangles.push_back(t);
  }
}

sim::world::Mesh wall_facing_minus_x(double distance_m) {
  sim::world::Mesh mesh;
  const float d = static_cast<float>(distance_m);
  // Corner at y = +20 going to y = -20 so that along x up points to -x.
  add_quad(mesh, {d, 20, -20}, {0, -40, 0}, {0, 0, 40}, {});
  return mesh;
}

namespace {

constexpr float kHeight = 2.8f;

void add_box(sim::world::Mesh& mesh, const Eigen::Vector3f& lo, const Eigen::Vector3f& hi,
             const QuadLook& look) {
  const Eigen::Vector3f s = hi - lo;
  const Eigen::Vector3f ex(s.x(), 0, 0), ey(0, s.y(), 0), ez(0, 0, s.z());
  add_quad(mesh, lo, ey, ez, look);             // -x face
  add_quad(mesh, lo + ex + ey, -ey, ez, look);  // +x face
  add_quad(mesh, lo + ex, -ex, ez, look);       // -y face
  add_quad(mesh, lo + ey, ex, ez, look);        // +y face
  add_quad(mesh, lo + ez, ex, ey, look);        // top
}

}  // namespace

HandCorridor hand_corridor() {
  HandCorridor c;
  sim::world::Mesh& m = c.mesh;
  for (int s = 0; s < 5; ++s) {
    const float x0 = 4.0f * s;
    // Left wall (y = 1, facing -y): along +x, up +z gives normal -y.
    add_quad(m, {x0, 1, 0}, {4, 0, 0}, {0, 0, kHeight}, {sim::world::SurfaceKind::kWall, 1 + s});
    // Right wall (y = -1, facing +y): along -x.
    add_quad(m, {x0 + 4, -1, 0}, {-4, 0, 0}, {0, 0, kHeight},
             {sim::world::SurfaceKind::kWall, 6 + s});
    add_quad(m, {x0, -1, 0}, {4, 0, 0}, {0, 2, 0},
             {sim::world::SurfaceKind::kFloor, 1 + s, -1, {x0, 0}});
    add_quad(m, {x0, 1, kHeight}, {4, 0, 0}, {0, -2, 0},
             {sim::world::SurfaceKind::kCeiling, 1 + s, -1, {x0, 0}});
    // Posters 1 cm in front of each wall.
    add_quad(m, {x0 + 1.2f, 0.99f, 1.1f}, {0.6f, 0, 0}, {0, 0, 0.85f},
             {sim::world::SurfaceKind::kPoster, 1 + s, 1000 + s});
    add_quad(m, {x0 + 2.8f, -0.99f, 1.1f}, {-0.6f, 0, 0}, {0, 0, 0.85f},
             {sim::world::SurfaceKind::kPoster, 6 + s, 2000 + s});
    c.lights.push_back({Eigen::Vector3d(x0 + 1.5, 0, kHeight), Eigen::Vector2d(0.6, 0.6)});
    c.lights.push_back({Eigen::Vector3d(x0 + 3.0, 0, kHeight), Eigen::Vector2d(0.6, 0.6)});
  }
  // Ceiling light panels just below the ceiling.
  for (const sim::world::CeilingLight& light : c.lights) {
    const Eigen::Vector3f p = light.center_m.cast<float>();
    add_quad(m, {p.x() - 0.3f, p.y() - 0.3f, kHeight - 0.01f}, {0.6f, 0, 0}, {0, 0.6f, 0},
             {sim::world::SurfaceKind::kLight});
  }
  // End walls.
  add_quad(m, {0, -1, 0}, {0, 2, 0}, {0, 0, kHeight}, {sim::world::SurfaceKind::kWall, 11});
  add_quad(m, {20, 1, 0}, {0, -2, 0}, {0, 0, kHeight}, {sim::world::SurfaceKind::kWall, 12});
  // A closed door 5 cm proud of the left wall, with a frame.
  add_box(m, {9.0f, 0.95f, 0.0f}, {9.9f, 1.0f, 2.1f}, {sim::world::SurfaceKind::kDoor, 3});
  add_box(m, {8.92f, 0.93f, 0.0f}, {9.0f, 1.0f, 2.18f}, {sim::world::SurfaceKind::kDoorFrame, 3});
  add_box(m, {9.9f, 0.93f, 0.0f}, {9.98f, 1.0f, 2.18f}, {sim::world::SurfaceKind::kDoorFrame, 3});
  // A square pillar in the middle of the corridor: strong depth edges.
  add_box(m, {13.0f, -0.2f, 0.0f}, {13.4f, 0.2f, kHeight}, {sim::world::SurfaceKind::kWall, 13});
  return c;
}

HandCorridor two_segment_wall(int variant_a, int variant_b) {
  HandCorridor c;
  sim::world::Mesh& m = c.mesh;
  const int variants[2] = {variant_a, variant_b};
  for (int s = 0; s < 2; ++s) {
    const float x0 = 4.0f * s;
    const int v = variants[s];
    // Texture coordinates restart at each segment, as the generator lays segments out.
    add_quad(m, {x0, 1, 0}, {4, 0, 0}, {0, 0, kHeight}, {sim::world::SurfaceKind::kWall, v});
    add_quad(m, {x0, -2, 0}, {4, 0, 0}, {0, 3, 0}, {sim::world::SurfaceKind::kFloor, v});
    add_quad(m, {x0, 1, kHeight}, {4, 0, 0}, {0, -3, 0}, {sim::world::SurfaceKind::kCeiling, v});
    add_quad(m, {x0 + 1.6f, 0.99f, 1.1f}, {0.6f, 0, 0}, {0, 0, 0.85f},
             {sim::world::SurfaceKind::kPoster, v, v == 0 ? 7 : 1000 + 16 * v});
    c.lights.push_back({Eigen::Vector3d(x0 + 2.0, 0, kHeight), Eigen::Vector2d(0.6, 0.6)});
  }
  return c;
}

}  // namespace wifislam::test
