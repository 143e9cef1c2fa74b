// The renderer on the shipped scenes: depth agrees with Embree ray casts from random poses along
// every scene's route. `wifislam render` is tested in render_cli_test.cpp.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "sim/render/rgbd_renderer.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/world/world_generator.hpp"
#include "tests/sim/render/embree_depth.hpp"

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

}  // namespace
}  // namespace wifislam::sim
