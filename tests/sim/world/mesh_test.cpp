#include <gtest/gtest.h>

#include <set>

#include <Eigen/Geometry>

#include "sim/world/plan_queries.hpp"
#include "sim/world/world_generator.hpp"
#include "tests/sim/world/world_test_support.hpp"

namespace wifislam::sim {
namespace {

double triangle_area(const world::Mesh& m, const world::Triangle& t) {
  return 0.5 * (m.positions_m[t.v[1]] - m.positions_m[t.v[0]])
                   .cross(m.positions_m[t.v[2]] - m.positions_m[t.v[0]])
                   .cast<double>()
                   .norm();
}

TEST(Mesh, SquareLoopWallsAreClosedAndFaceFreeSpace) {
  for (bool doors_open : {false, true}) {
    SCOPED_TRACE(doors_open ? "outside doors open" : "outside doors closed");
    const world::World world =
        world::generate_world(test::square_loop_scene(14.0, 2.0, doors_open));
    test::expect_mesh_invariants(world);
  }
}

TEST(Mesh, HasEverySurfaceKind) {
  const world::World world = world::generate_world(test::square_loop_scene());
  std::set<world::SurfaceKind> kinds;
  for (const world::Triangle& t : world.mesh.triangles) kinds.insert(t.surface);
  for (world::SurfaceKind k :
       {world::SurfaceKind::kWall, world::SurfaceKind::kFloor, world::SurfaceKind::kCeiling,
        world::SurfaceKind::kDoor, world::SurfaceKind::kDoorFrame, world::SurfaceKind::kPoster,
        world::SurfaceKind::kLight, world::SurfaceKind::kWallTop})
    EXPECT_TRUE(kinds.count(k)) << "missing surface kind " << static_cast<int>(k);
}

TEST(Mesh, FloorAndCeilingCoverExactlyTheFreeSpace) {
  const world::World world = world::generate_world(test::square_loop_scene());
  double floor = 0, ceiling = 0;
  for (const world::Triangle& t : world.mesh.triangles) {
    if (t.surface == world::SurfaceKind::kFloor) floor += triangle_area(world.mesh, t);
    if (t.surface == world::SurfaceKind::kCeiling) ceiling += triangle_area(world.mesh, t);
  }
  const double free_area = world::regions_area_m2(world.plan.free_space);
  EXPECT_NEAR(floor, free_area, 1e-4 * free_area);
  EXPECT_NEAR(ceiling, free_area, 1e-4 * free_area);
}

TEST(Mesh, ClosedDoorLeavesAreWoodInTheirOpeningBelowDoorHeight) {
  const world::World world = world::generate_world(test::square_loop_scene(14.0, 2.0, false));
  int leaves = 0;
  for (const world::Triangle& t : world.mesh.triangles) {
    if (t.surface != world::SurfaceKind::kDoor) continue;
    ++leaves;
    EXPECT_EQ(t.material, radio_model::WallMaterial::kWoodDoor);
    Eigen::Vector3f c = Eigen::Vector3f::Zero();
    for (auto v : t.v) c += world.mesh.positions_m[v] / 3;
    bool in_a_door = false;
    for (const world::Door& d : world.plan.doors) {
      const Eigen::Vector2d f = c.head<2>().cast<double>() - d.center_m;
      const Eigen::Vector2d n(-d.along_wall.y(), d.along_wall.x());
      in_a_door =
          in_a_door ||
          (!d.open && std::abs(f.dot(d.along_wall)) <= 0.5 * d.width_m + 1e-6 &&
           std::abs(f.dot(n)) <= 0.5 * d.wall_thickness_m + 1e-6 && c.z() <= d.height_m + 1e-6);
    }
    EXPECT_TRUE(in_a_door);
  }
  EXPECT_EQ(leaves, 16 * 2 * 2) << "two triangles on each face of 16 closed doors";
}

TEST(Mesh, WallTrianglesCarryTheirPhysicalWall) {
  const world::World world = world::generate_world(test::square_loop_scene());
  const int max_id = world.plan.wall_count + static_cast<int>(world.plan.doors.size());
  for (const world::Triangle& t : world.mesh.triangles) {
    if (t.surface == world::SurfaceKind::kWall || t.surface == world::SurfaceKind::kDoor) {
      EXPECT_GE(t.wall_id, 0);
      EXPECT_LT(t.wall_id, max_id);
    }
    if (t.surface == world::SurfaceKind::kFloor || t.surface == world::SurfaceKind::kCeiling ||
        t.surface == world::SurfaceKind::kLight || t.surface == world::SurfaceKind::kPoster) {
      EXPECT_EQ(t.wall_id, -1);
    }
  }
}

}  // namespace
}  // namespace wifislam::sim
