#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/error.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/world/plan_drawing.hpp"
#include "sim/world/world_generator.hpp"
#include "tests/sim/world/world_test_support.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::sim {
namespace {

std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(PlanDrawing, WritesPngAndSvgAtomically) {
  const world::World world = world::generate_world(test::square_loop_scene());
  const std::filesystem::path dir = test::scratch_folder();
  world::PlanDrawingOptions options;
  options.title = "square loop";
  options.access_points_m = {{3, 3, 2.5}, {10, -3, 2.5}};
  world::draw_floor_plan(world, dir / "plan.png", options);
  world::draw_floor_plan(world, dir / "plan.svg", options);
  const std::string png = read_all(dir / "plan.png");
  const std::string svg = read_all(dir / "plan.svg");
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_GT(png.size(), 10000u) << "a plan with walls, rooms and a route is not a blank image";
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "plan.png.partial"));
  EXPECT_FALSE(std::filesystem::exists(dir / "plan.svg.partial"));
}

// Imported plans have open doors between two walkable spaces, with no room: the drawing read the
// room of index -1 for the leaf's swing, and `world --plan` of a real scene crashed at random.
TEST(PlanDrawing, AnOpenDoorWithoutARoomIsDrawnAsAnOpening) {
  const world::World world = world::generate_world(sim::scene::load_scene_file(
      std::string(WIFISLAM_SCENES_DIR) + "/real/westport_house_level_2.yaml"));
  int roomless_open_doors = 0;
  for (const world::Door& d : world.plan.doors) roomless_open_doors += d.open && d.room_index < 0;
  ASSERT_GT(roomless_open_doors, 0) << "the scene no longer has the case this test draws";
  const std::filesystem::path dir = test::scratch_folder();
  world::draw_floor_plan(world, dir / "plan.png");
  world::draw_floor_plan(world, dir / "plan.svg");
  EXPECT_EQ(read_all(dir / "plan.png").substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_NE(read_all(dir / "plan.svg").find("<svg"), std::string::npos);
}

TEST(PlanDrawing, UnwritablePathIsAnIoError) {
  const world::World world = world::generate_world(test::square_loop_scene());
  EXPECT_THROW(world::draw_floor_plan(world, "/nonexistent-dir/plan.png"), IoError);
}

}  // namespace
}  // namespace wifislam::sim
