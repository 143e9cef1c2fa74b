// Consistency between the parts: the renderer's depth, the robot's ground-truth pose and the
// world's geometry must agree. Back-projecting a noise-free depth frame with its ground-truth
// pose lands the points on the world's walls and floor.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/median.hpp"
#include "sim/generate/generation_pipeline.hpp"
#include "sim/generate/generator_stream.hpp"
#include "tests/sim/generate/test_scene.hpp"

namespace wifislam::sim {
namespace {

double distance_to_segment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                           const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

TEST(GenerateConsistency, NoiseFreeDepthBackProjectsOntoTheWorldsWalls) {
  scene::Scene scene = test::small_scene();
  scene.sensors.depth.noise = false;
  scene.sensors.depth.quantisation = false;
  scene.sensors.depth.dropouts = false;
  generate::GenerateOptions options;
  options.fps = 0.5;  // one frame every 2 s: views from all along the route
  generate::GeneratorStream stream(scene, options);
  const world::World& world = stream.pipeline().world();
  const double wall_height_m = world.plan.wall_height_m;
  const CameraIntrinsics& k = stream.intrinsics();

  std::vector<double> wall_distances_m, floor_heights_m;
  int frames = 0;
  while (auto event = stream.next()) {
    const auto* frame = std::get_if<RgbdFrame>(&*event);
    if (!frame) continue;
    ++frames;
    const Pose& camera_to_world = stream.last_frame_ground_truth();
    for (int v = 2; v < k.height_px; v += 8) {
      for (int u = 2; u < k.width_px; u += 8) {
        const float z = frame->depth_m.at<float>(v, u);
        if (z <= 0.0f) continue;
        const Eigen::Vector3d p = camera_to_world * k.back_project(u, v, z);
        if (p.z() < 0.02) {
          floor_heights_m.push_back(std::abs(p.z()));
        } else if (p.z() > 0.1 && p.z() < wall_height_m - 0.1) {
          double best = 1e9;
          for (const world::WallFace2& f : world.plan.wall_faces)
            best = std::min(best, distance_to_segment(p.head<2>(), f.a_m, f.b_m));
          wall_distances_m.push_back(best);
        }
      }
    }
  }
  EXPECT_GT(frames, 20);
  ASSERT_GT(wall_distances_m.size(), 10000u);
  EXPECT_LT(median(wall_distances_m), 0.01);
  ASSERT_GT(floor_heights_m.size(), 1000u);
  EXPECT_LT(median(floor_heights_m), 0.01);
}

}  // namespace
}  // namespace wifislam::sim
