// The renderer on the shipped scenes: depth agrees with Embree ray casts from random poses along
// every scene's route, and `wifislam render` writes byte-identical files in separate processes.

#include <gtest/gtest.h>

#include <unistd.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <sys/wait.h>

#include "core/rng.hpp"
#include "sim/render/depth_png.hpp"
#include "sim/render/rgbd_renderer.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/world/world_generator.hpp"
#include "tests/sim/render/embree_depth.hpp"
#include "tests/support/read_file.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::sim {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> shipped_scenes() {
  std::vector<fs::path> scenes;
  for (const auto& entry : fs::directory_iterator(WIFISLAM_SCENES_DIR)) {
    if (entry.path().extension() == ".yaml") scenes.push_back(entry.path());
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

TEST(SceneRender, EveryShippedSceneMatchesEmbreeFromRandomRoutePoses) {
  const std::vector<fs::path> scenes = shipped_scenes();
  ASSERT_GE(scenes.size(), 1u);
  for (const fs::path& path : scenes) {
    const scene::Scene scene = scene::load_scene_file(path.string());
    const world::World world = world::generate_world(scene);
    ASSERT_FALSE(world.route.points_m.empty()) << path;
    const CameraIntrinsics k = scene.sensors.camera.intrinsics;
    render::RgbdRenderer renderer(k);
    renderer.set_world(world, scene);
    const test::EmbreeDepth ray_caster(world.mesh);
    Rng rng = Rng::stream(scene.seed, "test/render_poses");
    long compared = 0, agreeing = 0;
    for (int i = 0; i < 6; ++i) {
      // A point on the route (walkable, clear of walls), looking roughly along it.
      const auto at = static_cast<std::size_t>(
          rng.uniform_int(0, static_cast<std::int64_t>(world.route.points_m.size()) - 1));
      const Eigen::Vector2d p = world.route.points_m[at];
      const Pose pose = camera_pose_from_planar(
          p.x(), p.y(), world.route.heading_rad[at] + rng.uniform(-1.0, 1.0),
          scene.sensors.camera.height_m, rng.uniform(-0.2, 0.2));
      const cv::Mat rendered = renderer.render(pose).depth_m;
      const cv::Mat cast =
          ray_caster.depth(k, pose, renderer.options().near_m, renderer.options().far_m);
      for (int v = 0; v < rendered.rows; ++v) {
        for (int u = 0; u < rendered.cols; ++u) {
          const float r = rendered.at<float>(v, u), e = cast.at<float>(v, u);
          if (r <= 0.0f && e <= 0.0f) continue;
          ++compared;
          if (r > 0.0f && e > 0.0f && std::abs(r - e) <= 0.01f) ++agreeing;
        }
      }
    }
    const double fraction = static_cast<double>(agreeing) / static_cast<double>(compared);
    std::printf("%s: depth within 1 cm of Embree for %.4f %% of %ld pixels with a reading\n",
                path.filename().c_str(), 100.0 * fraction, compared);
    EXPECT_GT(compared, 6L * k.width_px * k.height_px / 2) << path;
    EXPECT_GE(fraction, 0.995) << path;
  }
}

TEST(SceneRender, RenderCommandIsByteIdenticalAcrossProcesses) {
  const fs::path dir = test::scratch_folder();
  const fs::path scene_path = fs::path(WIFISLAM_SCENES_DIR) / "aliasing_ladder.yaml";
  const scene::Scene scene = scene::load_scene_file(scene_path.string());
  const world::World world = world::generate_world(scene);
  const Eigen::Vector2d p = world.route.points_m[world.route.points_m.size() / 3];
  const double yaw_deg =
      world.route.heading_rad[world.route.points_m.size() / 3] * 180.0 / std::numbers::pi;
  for (const char* name : {"a", "b"}) {
    const std::string command =
        fmt::format("{} render {} --pose {},{},{} -o {} > /dev/null", WIFISLAM_BINARY,
                    scene_path.string(), p.x(), p.y(), yaw_deg, (dir / name).string());
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
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

TEST(SceneRender, RenderCommandRejectsAMalformedPose) {
  const std::string command =
      fmt::format("{} render {}/aliasing_ladder.yaml --pose 1,2 -o /tmp/x 2> /dev/null",
                  WIFISLAM_BINARY, WIFISLAM_SCENES_DIR);
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
}

}  // namespace
}  // namespace wifislam::sim
