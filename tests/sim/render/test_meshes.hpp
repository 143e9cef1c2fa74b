#pragma once
// Hand-built meshes for the renderer tests: known geometry, independent of the world generator.

#include <vector>

#include <Eigen/Core>

#include "sim/world/world_types.hpp"

namespace wifislam::test {

struct QuadLook {
  sim::world::SurfaceKind surface = sim::world::SurfaceKind::kWall;
  int variant = 0;
  int decoration = -1;
  Eigen::Vector2f uv_origin_m = Eigen::Vector2f::Zero();
};

/// Appends the quad corner, corner + along, corner + along + up, corner + up (two triangles,
/// normal along x up), with uv in metres from `uv_origin_m`.
void add_quad(sim::world::Mesh& mesh, const Eigen::Vector3f& corner, const Eigen::Vector3f& along,
              const Eigen::Vector3f& up, const QuadLook& look);

/// A plane x = distance_m (normal towards -x), 40 m x 40 m, centred on (distance_m, 0, 0).
sim::world::Mesh wall_facing_minus_x(double distance_m);

/// A corridor along +x from x = 0 to 20 m, y in [-1, 1], 2.8 m high: floor, ceiling, walls in
/// 4 m appearance segments (variants 1..5 left, 6..10 right), posters 1 cm off the walls, a door
/// recess, a pillar in the middle (depth edges) and end walls. Lights every 3 m.
struct HandCorridor {
  sim::world::Mesh mesh;
  std::vector<sim::world::CeilingLight> lights;
};
HandCorridor hand_corridor();

/// One wall along +x at y = 1 (facing -y) made of two 4 m segments with the given variants,
/// each with floor and ceiling of the same variant and one poster at the same relative place.
/// Poster designs follow the world generator's rule: a shared design for variant 0, a unique
/// one per unique variant.
HandCorridor two_segment_wall(int variant_a, int variant_b);

}  // namespace wifislam::test
