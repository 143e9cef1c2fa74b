// The counting rule of embree_wall_scene.hpp on a generated world: the world's mesh must carry
// normals toward free space on every face that bounds a wall (the rule reads the material's side
// from them), and a closed door leaf next to its wall counts as one wall, as on hand-built
// geometry (wall_counting_test.cpp). On j_hall the old rule counted the leaf and the wall beside
// it for a ray through the leaf's edge: -51 dBm where the leaf alone gives -36.5 dBm.
#include <gtest/gtest.h>

#include <set>

#include "radio_model/embree_wall_scene.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/world/radio_wall_mesh.hpp"
#include "sim/world/world_generator.hpp"

namespace wifislam::radio_model {
namespace {

TEST(WallCountingOnAWorld, EveryClosedDoorOfJHallIsOneWallThroughTheLeafAndThroughItsEdge) {
  const sim::scene::Scene scene =
      sim::scene::load_scene_file(std::string(WIFISLAM_SCENES_DIR) + "/j_hall.yaml");
  const sim::world::World world = sim::world::generate_world(scene);
  const EmbreeWallScene walls(sim::world::radio_wall_mesh(world.mesh));
  int closed = 0;
  for (const sim::world::Door& door : world.plan.doors) {
    if (door.open) continue;
    ++closed;
    const Eigen::Vector2d u = door.along_wall, n(-u.y(), u.x());
    const double hw = 0.5 * door.width_m, ht = 0.5 * door.wall_thickness_m;
    auto at = [&](const Eigen::Vector2d& p, double z) { return Eigen::Vector3d(p.x(), p.y(), z); };
    // Square through the middle of the leaf: one wooden wall.
    const auto leaf =
        walls.walls_crossed(at(door.center_m - 1.5 * n, 1.0), at(door.center_m + 1.5 * n, 1.0));
    ASSERT_EQ(leaf.size(), 1u) << "door at " << door.center_m.transpose();
    EXPECT_EQ(leaf[0].material, radio_model::WallMaterial::kWoodDoor);
    EXPECT_EQ(leaf[0].exit_material, radio_model::WallMaterial::kWoodDoor);
    EXPECT_NEAR(leaf[0].length_m, door.wall_thickness_m, 1e-3);
    // Into the leaf 5 cm from its edge, out of the wall 5 cm beyond it: one wall of two
    // materials. The line runs on 1 m either side, so it starts and ends in free space.
    const Eigen::Vector2d in = door.center_m - ht * n + (hw - 0.05) * u;
    const Eigen::Vector2d out = door.center_m + ht * n + (hw + 0.05) * u;
    const Eigen::Vector2d step = (out - in).normalized();
    const auto edge = walls.walls_crossed(at(in - step, 1.0), at(out + step, 1.0));
    ASSERT_EQ(edge.size(), 1u) << "door at " << door.center_m.transpose();
    const std::set<radio_model::WallMaterial> materials = {edge[0].material, edge[0].exit_material};
    EXPECT_TRUE(materials.count(radio_model::WallMaterial::kWoodDoor)) << door.center_m.transpose();
    EXPECT_EQ(materials.size(), 2u) << door.center_m.transpose();
  }
  EXPECT_GT(closed, 20);
}

}  // namespace
}  // namespace wifislam::radio_model
