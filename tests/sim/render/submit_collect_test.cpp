// A view submitted ahead and collected later (the generator's render path: frame k+1 rasterizes
// while frame k goes through the sensor models) is the view render() gives, byte for byte, also
// when another renderer draws in between; misuse is a clear error.

#include <gtest/gtest.h>

#include <stdexcept>

#include <opencv2/core.hpp>

#include "core/pose.hpp"
#include "sim/render/rgbd_renderer.hpp"
#include "tests/sim/render/test_meshes.hpp"

namespace wifislam::sim {
namespace {

bool same_bytes(const cv::Mat& a, const cv::Mat& b) {
  return a.type() == b.type() && a.size() == b.size() &&
         cv::countNonZero(a.reshape(1) != b.reshape(1)) == 0;
}

void expect_same_view(const render::RenderedView& a, const render::RenderedView& b,
                      const char* what) {
  EXPECT_TRUE(same_bytes(a.color_bgr, b.color_bgr)) << what;
  EXPECT_TRUE(same_bytes(a.depth_m, b.depth_m)) << what;
  EXPECT_TRUE(same_bytes(a.incidence_cos, b.incidence_cos)) << what;
}

TEST(RenderSubmitCollect, SubmittedAheadIsTheRenderedView) {
  const test::HandCorridor corridor = test::hand_corridor();
  const Pose a = camera_pose_from_planar(2.0, 0.2, 0.1, 0.5);
  const Pose b = camera_pose_from_planar(12.0, -0.3, 3.0, 0.5);
  render::RgbdRenderer renderer(CameraIntrinsics::kinect_v1());
  renderer.set_world(corridor.mesh, corridor.lights, 5, scene::AppearanceThemes{});
  const render::RenderedView rendered_a = renderer.render(a);
  const render::RenderedView rendered_b = renderer.render(b);
  ASSERT_GT(cv::countNonZero(rendered_a.depth_m), 100000);
  ASSERT_FALSE(same_bytes(rendered_a.color_bgr, rendered_b.color_bgr));

  // Another renderer (its own context) draws a whole frame while b is in flight.
  render::RgbdRenderer other(CameraIntrinsics::kinect_v1());
  other.set_world(test::wall_facing_minus_x(2.0), {}, 1, scene::AppearanceThemes{});

  render::RenderedView view;  // one buffer, reused as the pipeline does
  renderer.submit(a);
  EXPECT_TRUE(renderer.has_submitted());
  renderer.collect(view);
  EXPECT_FALSE(renderer.has_submitted());
  expect_same_view(view, rendered_a, "a, collected");
  renderer.submit(b);
  const render::RenderedView between = other.render(camera_pose_from_planar(0.0, 0.0, 0.0, 0.0));
  EXPECT_GT(cv::countNonZero(between.depth_m), 100000);
  renderer.collect(view);
  expect_same_view(view, rendered_b, "b, collected after another renderer drew");
  // And rendering in one call after a submit/collect pair is unchanged.
  expect_same_view(renderer.render(a), rendered_a, "a again");
}

TEST(RenderSubmitCollect, OneViewAtATime) {
  render::RgbdRenderer renderer(CameraIntrinsics::kinect_v1());
  renderer.set_world(test::wall_facing_minus_x(2.0), {}, 1, scene::AppearanceThemes{});
  render::RenderedView view;
  EXPECT_THROW(renderer.collect(view), std::logic_error);
  const Pose pose = camera_pose_from_planar(0.0, 0.0, 0.0, 0.0);
  renderer.submit(pose);
  EXPECT_THROW(renderer.submit(pose), std::logic_error);
  EXPECT_THROW(renderer.render(pose), std::logic_error);
  renderer.collect(view);
  EXPECT_NEAR(view.depth_m.at<float>(240, 320), 2.0f, 1e-3f);
  EXPECT_THROW(renderer.collect(view), std::logic_error);
  // A renderer destroyed with a view in flight is fine (the driver keeps what it still uses).
  render::RgbdRenderer dropped(CameraIntrinsics::kinect_v1());
  dropped.set_world(test::wall_facing_minus_x(3.0), {}, 1, scene::AppearanceThemes{});
  dropped.submit(pose);
}

}  // namespace
}  // namespace wifislam::sim
