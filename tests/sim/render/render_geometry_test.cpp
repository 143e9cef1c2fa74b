// The renderer's depth is metric and exact: known walls read their distance, and a second,
// independent engine (Embree ray casting) agrees with it pixel by pixel.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/pose.hpp"
#include "core/rng.hpp"
#include "sim/render/osmesa_context.hpp"
#include "sim/render/rgbd_renderer.hpp"
#include "tests/sim/render/embree_depth.hpp"
#include "tests/sim/render/test_meshes.hpp"

namespace wifislam::sim {
namespace {

struct Agreement {
  int compared = 0;  // pixels where either engine has a reading
  int agreeing = 0;  // both have one, within the tolerance
  double fraction() const { return compared == 0 ? 0.0 : static_cast<double>(agreeing) / compared; }
};

Agreement compare_depth(const cv::Mat& rendered, const cv::Mat& ray_cast, double tolerance_m) {
  Agreement a;
  for (int v = 0; v < rendered.rows; ++v) {
    for (int u = 0; u < rendered.cols; ++u) {
      const float r = rendered.at<float>(v, u), e = ray_cast.at<float>(v, u);
      if (r <= 0.0f && e <= 0.0f) continue;
      ++a.compared;
      if (r > 0.0f && e > 0.0f && std::abs(r - e) <= tolerance_m) ++a.agreeing;
    }
  }
  return a;
}

TEST(RenderGeometry, ContextIsOpenGl33CoreOnLlvmpipe) {
  render::RgbdRenderer renderer(CameraIntrinsics::kinect_v1());
  const std::string& version = renderer.context().gl_version();
  ASSERT_GE(version.size(), 3u);
  EXPECT_GE(std::stod(version.substr(0, 3)), 3.3) << version;
  EXPECT_NE(renderer.context().gl_renderer().find("llvmpipe"), std::string::npos)
      << renderer.context().gl_renderer();
}

TEST(RenderGeometry, WallFacingTheCameraReadsItsDistanceEverywhere) {
  render::RgbdRenderer renderer(CameraIntrinsics::kinect_v1());
  for (const double distance_m : {1.0, 2.0, 3.5}) {
    renderer.set_world(test::wall_facing_minus_x(distance_m), {}, 1, scene::AppearanceThemes{});
    const render::RenderedView view = renderer.render(camera_pose_from_planar(0.0, 0.0, 0.0, 0.0));
    EXPECT_NEAR(view.depth_m.at<float>(240, 320), distance_m, 1e-3) << distance_m;
    double worst_m = 0.0;
    for (int v = 0; v < view.depth_m.rows; ++v) {
      for (int u = 0; u < view.depth_m.cols; ++u) {
        worst_m = std::max(worst_m, std::abs(view.depth_m.at<float>(v, u) - distance_m));
      }
    }
    EXPECT_LT(worst_m, 1e-3) << "distance " << distance_m;
    // Fronto-parallel: the ray meets the surface head-on at the centre.
    EXPECT_NEAR(view.incidence_cos.at<float>(240, 320), 1.0, 1e-3);
  }
}

TEST(RenderGeometry, TiltedWallBackProjectsOntoItsPlane) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  render::RgbdRenderer renderer(k);
  renderer.set_world(test::wall_facing_minus_x(2.5), {}, 1, scene::AppearanceThemes{});
  // Camera yawed by 35 deg and pitched by 10 deg: depth varies across the image.
  const Pose pose = camera_pose_from_planar(0.0, 0.0, 35.0 * std::numbers::pi / 180.0, 0.3,
                                            10.0 * std::numbers::pi / 180.0);
  const render::RenderedView view = renderer.render(pose);
  double worst_m = 0.0, worst_cos = 0.0;
  int pixels = 0;
  for (int v = 0; v < k.height_px; v += 3) {
    for (int u = 0; u < k.width_px; u += 3) {
      const float z = view.depth_m.at<float>(v, u);
      ASSERT_GT(z, 0.0f) << u << "," << v;
      const Eigen::Vector3d ray = pose.linear() * k.back_project(u, v, 1.0);
      const Eigen::Vector3d world = pose * k.back_project(u, v, z);
      worst_m = std::max(worst_m, std::abs(world.x() - 2.5));
      // Incidence against the plane's normal (-x).
      worst_cos = std::max(
          worst_cos, std::abs(view.incidence_cos.at<float>(v, u) - std::abs(ray.normalized().x())));
      ++pixels;
    }
  }
  EXPECT_GT(pixels, 30000);
  EXPECT_LT(worst_m, 1e-3);
  EXPECT_LT(worst_cos, 2.5e-3);  // incidence is read back in 8 bits: steps of 1/255
}

TEST(RenderGeometry, RenderedDepthAgreesWithEmbreeInHandBuiltCorridor) {
  const test::HandCorridor corridor = test::hand_corridor();
  const test::EmbreeDepth ray_caster(corridor.mesh);
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  render::RgbdRenderer renderer(k);
  renderer.set_world(corridor.mesh, corridor.lights, 5, scene::AppearanceThemes{});
  Rng rng = Rng::stream(5, "test/corridor_poses");
  Agreement total;
  for (int i = 0; i < 12; ++i) {
    const Pose pose = camera_pose_from_planar(rng.uniform(0.5, 19.5), rng.uniform(-0.7, 0.7),
                                              rng.uniform(-std::numbers::pi, std::numbers::pi),
                                              rng.uniform(0.3, 1.8), rng.uniform(-0.3, 0.3));
    const Agreement a = compare_depth(
        renderer.render(pose).depth_m,
        ray_caster.depth(k, pose, renderer.options().near_m, renderer.options().far_m), 0.01);
    EXPECT_GE(a.fraction(), 0.995) << "pose " << i;
    total.compared += a.compared;
    total.agreeing += a.agreeing;
  }
  RecordProperty("depth_agreement_percent", std::to_string(100.0 * total.fraction()));
  std::printf("depth agreement with Embree, hand corridor: %.4f %% of %d pixels\n",
              100.0 * total.fraction(), total.compared);
}

TEST(RenderGeometry, OffCentreIntrinsicsAgreeWithEmbree) {
  // A principal point away from the centre and unequal focal lengths catch any mix-up between
  // the intrinsics and the projection matrix (including the half-pixel convention).
  CameraIntrinsics k;
  k.width_px = 320;
  k.height_px = 200;
  k.fx_px = 280.0;
  k.fy_px = 250.0;
  k.cx_px = 140.25;
  k.cy_px = 110.75;
  const test::HandCorridor corridor = test::hand_corridor();
  const test::EmbreeDepth ray_caster(corridor.mesh);
  render::RgbdRenderer renderer(k);
  renderer.set_world(corridor.mesh, corridor.lights, 5, scene::AppearanceThemes{});
  const Pose pose = camera_pose_from_planar(11.0, 0.4, -0.2, 1.0, 0.1);
  const Agreement a =
      compare_depth(renderer.render(pose).depth_m, ray_caster.depth(k, pose, 0.05, 40.0), 0.01);
  EXPECT_GT(a.compared, 60000);
  EXPECT_GE(a.fraction(), 0.995);
}

TEST(RenderGeometry, ColourShowsTexturedLitSurfaces) {
  const test::HandCorridor corridor = test::hand_corridor();
  render::RgbdRenderer renderer(CameraIntrinsics::kinect_v1());
  renderer.set_world(corridor.mesh, corridor.lights, 5, scene::AppearanceThemes{});
  const render::RenderedView view = renderer.render(camera_pose_from_planar(2.0, 0.0, 0.0, 1.2));
  cv::Scalar mean, stddev;
  cv::meanStdDev(view.color_bgr, mean, stddev);
  EXPECT_GT(mean[1], 60.0);    // lit, not black
  EXPECT_LT(mean[1], 235.0);   // not blown out
  EXPECT_GT(stddev[1], 15.0);  // structure: posters, floor tiles, ceiling lights, pillar
  // Every pixel sees the closed corridor.
  EXPECT_EQ(cv::countNonZero(view.depth_m <= 0.0f), 0);
}

}  // namespace
}  // namespace wifislam::sim
