// `wifislam render` through the command line: byte-identical files in separate processes, a TUM
// depth image, and a malformed pose refused.

#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>
#include <string>

#include <fmt/core.h>

#include "sim/render/depth_png.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/world/world_generator.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"

namespace wifislam::sim {
namespace {

namespace fs = std::filesystem;

TEST(SceneRender, RenderCommandIsByteIdenticalAcrossProcesses) {
  const fs::path dir = test::scratch_folder();
  const fs::path scene_path = fs::path(WIFISLAM_SCENES_DIR) / "aliasing_ladder.yaml";
  const scene::Scene scene = scene::load_scene_file(scene_path.string());
  const world::World world = world::generate_world(scene);
  const Eigen::Vector2d p = world.route.points_m[world.route.points_m.size() / 3];
  const double yaw_deg =
      world.route.heading_rad[world.route.points_m.size() / 3] * 180.0 / std::numbers::pi;
  // The second spells the pose with spaces after the commas, as people write it.
  for (const char* name : {"a", "b"}) {
    const char* separator = name[0] == 'a' ? "," : ", ";
    const test::CliResult r = test::run_wifislam(
        fmt::format("render {} --pose '{}{}{}{}{}' -o {}", scene_path.string(), p.x(), separator,
                    p.y(), separator, yaw_deg, (dir / name).string()),
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;  // a pose on the route
  }
  for (const char* suffix : {"_rgb.png", "_depth.png", "_depth_color.png"}) {
    const std::string a = test::read_file(dir.string() + "/a" + suffix);
    EXPECT_GT(a.size(), 5000u) << suffix;
    EXPECT_TRUE(a == test::read_file(dir.string() + "/b" + suffix)) << suffix;
  }
  // The depth file is a TUM depth image with readings in the sensor's range.
  const cv::Mat depth = render::read_depth_png(dir / "a_depth.png");
  EXPECT_EQ(depth.cols, scene.sensors.camera.intrinsics.width_px);
  double lo = 0, hi = 0;
  cv::minMaxLoc(depth, &lo, &hi, nullptr, nullptr, depth > 0.0f);
  EXPECT_GE(lo, scene.sensors.depth.min_range_m - 1e-3);
  EXPECT_LE(hi, scene.sensors.depth.max_range_m + 1e-3);
  EXPECT_GT(cv::countNonZero(depth > 0.0f), static_cast<int>(depth.total() / 4));
  fs::remove_all(dir);
}

// A view from the hole between two rungs of the ladder (inside the walls) or from far outside
// the building was drawn blank without a word. It is still drawn, with a warning.
TEST(SceneRender, APoseOutsideTheFreeSpaceIsDrawnWithAWarning) {
  const fs::path dir = test::scratch_folder();
  for (const char* pose : {"15,6,0", "-500,5,90"}) {
    const test::CliResult r =
        test::run_wifislam(fmt::format("render {}/aliasing_ladder.yaml --pose '{}' -o {}",
                                       WIFISLAM_SCENES_DIR, pose, (dir / "x").string()),
                           dir);
    EXPECT_EQ(r.exit_code, 0) << pose << ": " << r.err;
    EXPECT_NE(r.err.find("is not in the free space of scene 'aliasing_ladder'"), std::string::npos)
        << r.err;
    EXPECT_TRUE(fs::exists(dir / "x_rgb.png")) << pose;
  }
  fs::remove_all(dir);
}

TEST(SceneRender, RenderCommandRejectsAMalformedPose) {
  const fs::path dir = test::scratch_folder();
  // Two numbers; hexadecimal and infinity (which std::stod took); a place beyond the 10 km every
  // scene lies within; an empty field.
  for (const char* pose : {"1,2", "0x10,2,3", "inf,2,3", "1,2,nan", "20000,0,0", "1,,3"}) {
    const test::CliResult r =
        test::run_wifislam(fmt::format("render {}/aliasing_ladder.yaml --pose '{}' -o {}",
                                       WIFISLAM_SCENES_DIR, pose, (dir / "x").string()),
                           dir);
    EXPECT_EQ(r.signal, 0) << pose;
    EXPECT_EQ(r.exit_code, 2) << pose << ": " << r.err;
    EXPECT_NE(r.err.find("--pose"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(pose), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "x_rgb.png")) << pose;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace wifislam::sim
