#include "sim/world/radio_wall_mesh.hpp"

namespace wifislam::sim {

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

}  // namespace wifislam::sim
