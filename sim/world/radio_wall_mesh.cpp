#include "sim/world/radio_wall_mesh.hpp"

#include <algorithm>
#include <cmath>

#include "sim/world/plan_queries.hpp"

namespace wifislam::sim::world {

radio_model::WallMesh radio_wall_mesh(const Mesh& mesh) {
  radio_model::WallMesh walls;
  walls.positions_m = mesh.positions_m;
  for (const Triangle& tri : mesh.triangles) {
    if (tri.wall_id < 0) continue;
    radio_model::WallMesh::Face face;
    face.v = {tri.v[0], tri.v[1], tri.v[2]};
    face.wall_id = tri.wall_id;
    face.material = tri.material;
    // A vertex out of range is the radio model's to report (EmbreeWallScene checks every index).
    if (tri.v[0] < mesh.normals.size()) face.free_side = mesh.normals[tri.v[0]];
    walls.faces.push_back(face);
  }
  return walls;
}

namespace {

/// Appends `part` to `into`, its vertex indices and wall ids moved past those already there.
void append(radio_model::WallMesh& into, const radio_model::WallMesh& part, int& next_wall_id) {
  const auto base = static_cast<std::uint32_t>(into.positions_m.size());
  into.positions_m.insert(into.positions_m.end(), part.positions_m.begin(), part.positions_m.end());
  int top = -1;
  for (radio_model::WallMesh::Face face : part.faces) {
    for (std::uint32_t& v : face.v) v += base;
    top = std::max(top, face.wall_id);
    face.wall_id += next_wall_id;
    into.faces.push_back(face);
  }
  next_wall_id += top + 1;
}

/// The tops of the storey's walls, as faces of the walls they close. In one storey no link
/// passes through a wall's top (access points and receivers stand below it), so the mesh's
/// walls are open there; between storeys a link from below leaves a wall through its top, and
/// without the top the counting rule could not tell where the material ends. Each cap triangle
/// takes the wall id and material of the wall face nearest its centre.
void add_wall_tops(const Storey& storey, radio_model::WallMesh& walls) {
  const Mesh& mesh = storey.mesh;
  const float top_z = static_cast<float>(storey.elevation_m + storey.plan.wall_height_m);
  for (const Triangle& tri : mesh.triangles) {
    if (tri.surface != SurfaceKind::kWallTop) continue;
    const Eigen::Vector3f& p0 = mesh.positions_m[tri.v[0]];
    if (std::abs(p0.z() - top_z) > 1e-3f) continue;  // the bottom caps lie on the slab
    const Eigen::Vector3f centre =
        (p0 + mesh.positions_m[tri.v[1]] + mesh.positions_m[tri.v[2]]) / 3.0f;
    int face_index = -1;
    nearest_wall_distance_m(storey.plan, centre.head<2>().cast<double>(), &face_index);
    if (face_index < 0) continue;
    const WallFace2* nearest = &storey.plan.wall_faces[static_cast<std::size_t>(face_index)];
    if (nearest->wall_id < 0) continue;
    radio_model::WallMesh::Face face;
    face.v = {tri.v[0], tri.v[1], tri.v[2]};
    face.wall_id = nearest->wall_id;
    face.material = nearest->material;
    face.free_side = Eigen::Vector3f::UnitZ();
    walls.faces.push_back(face);
  }
}

/// The slab under `storey`: a closed box, its faces wound counter-clockwise seen from outside
/// and their free side outward.
radio_model::WallMesh slab_box(const Storey& storey) {
  const Eigen::Vector2d lo = storey.plan.bounds_min_m, hi = storey.plan.bounds_max_m;
  const double z0 = storey.elevation_m - storey.slab_thickness_m, z1 = storey.elevation_m;
  radio_model::WallMesh box;
  for (int i = 0; i < 8; ++i) {
    box.positions_m.emplace_back(static_cast<float>(i & 1 ? hi.x() : lo.x()),
                                 static_cast<float>(i & 2 ? hi.y() : lo.y()),
                                 static_cast<float>(i & 4 ? z1 : z0));
  }
  // Corners: bit 0 = x high, bit 1 = y high, bit 2 = z high. Each quad a, b, c, d counter-
  // clockwise seen from outside, with its outward normal.
  const struct {
    std::uint32_t a, b, c, d;
    Eigen::Vector3f out;
  } quads[] = {{4, 5, 7, 6, Eigen::Vector3f::UnitZ()},  {0, 2, 3, 1, -Eigen::Vector3f::UnitZ()},
               {0, 1, 5, 4, -Eigen::Vector3f::UnitY()}, {2, 6, 7, 3, Eigen::Vector3f::UnitY()},
               {0, 4, 6, 2, -Eigen::Vector3f::UnitX()}, {1, 3, 7, 5, Eigen::Vector3f::UnitX()}};
  for (const auto& q : quads) {
    for (const std::array<std::uint32_t, 3>& v : {std::array<std::uint32_t, 3>{q.a, q.b, q.c},
                                                  std::array<std::uint32_t, 3>{q.a, q.c, q.d}}) {
      radio_model::WallMesh::Face face;
      face.v = v;
      face.wall_id = 0;
      face.material = storey.slab_material;
      face.free_side = q.out;
      face.slab = true;
      box.faces.push_back(face);
    }
  }
  return box;
}

}  // namespace

radio_model::WallMesh radio_wall_mesh(const World& world) {
  if (world.storeys.empty()) return radio_wall_mesh(world.mesh);
  radio_model::WallMesh walls;
  int next_wall_id = 0;
  for (std::size_t k = 0; k < world.storeys.size(); ++k) {
    const Storey& storey = world.storeys[k];
    radio_model::WallMesh storey_walls = radio_wall_mesh(storey.mesh);
    add_wall_tops(storey, storey_walls);
    append(walls, storey_walls, next_wall_id);
    if (k > 0) append(walls, slab_box(storey), next_wall_id);  // nothing lies under the lowest
  }
  return walls;
}

void building_bounds(const World& world, Eigen::Vector2d& min_m, Eigen::Vector2d& max_m) {
  min_m = world.plan.bounds_min_m;
  max_m = world.plan.bounds_max_m;
  for (const Storey& storey : world.storeys) {
    min_m = min_m.cwiseMin(storey.plan.bounds_min_m);
    max_m = max_m.cwiseMax(storey.plan.bounds_max_m);
  }
}

}  // namespace wifislam::sim::world
