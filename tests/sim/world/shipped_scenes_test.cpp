// Every shipped scene file generates a world that meets the floor-plan and mesh invariants.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "sim/scene/scene_loader.hpp"
#include "sim/world/world_generator.hpp"
#include "tests/sim/world/world_test_support.hpp"

namespace wifislam::sim {
namespace {

std::vector<std::string> shipped_scenes() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(WIFISLAM_SCENES_DIR))
    if (entry.path().extension() == ".yaml") files.push_back(entry.path().stem().string());
  std::sort(files.begin(), files.end());
  return files;
}

class ShippedScene : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedScene, WorldMeetsPlanAndMeshInvariants) {
  const std::string path = std::string(WIFISLAM_SCENES_DIR) + "/" + GetParam() + ".yaml";
  const scene::Scene scene = scene::load_scene_file(path);
  const world::World world = world::generate_world(scene);
  test::expect_plan_invariants(scene, world);
  test::expect_mesh_invariants(world);
  EXPECT_EQ(world::mesh_hash(world.mesh), world::mesh_hash(world::generate_world(scene).mesh));
}

TEST(ShippedScenes, AllFivePaperAndStressScenesAreThere) {
  const auto files = shipped_scenes();
  for (const char* name : {"a_hall", "b_hall", "c_hall", "j_hall", "aliasing_ladder"})
    EXPECT_NE(std::find(files.begin(), files.end(), name), files.end()) << name;
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShippedScene, ::testing::ValuesIn(shipped_scenes()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace wifislam::sim
