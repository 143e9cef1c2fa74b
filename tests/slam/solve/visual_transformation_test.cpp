// The visual transformation between two real renders of a generated world (noise off): the
// recovered relative pose matches the true one, and a pair of views of different places is
// rejected.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>

#include "core/pose.hpp"
#include "sim/render/rgbd_renderer.hpp"
#include "sim/world/world_generator.hpp"
#include "slam/feature/orb_feature_extractor.hpp"
#include "slam/solve/visual_transformation.hpp"
#include "tests/slam/slam_test_scene.hpp"

namespace wifislam {
namespace {

class RenderedWorld : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new sim::scene::Scene(test::small_loop_scene());
    world_ = new sim::world::World(sim::world::generate_world(*scene_));
    renderer_ = new sim::render::RgbdRenderer(scene_->sensors.camera.intrinsics);
    renderer_->set_world(*world_, *scene_);
  }
  static void TearDownTestSuite() {
    delete renderer_;
    delete world_;
    delete scene_;
  }

  /// Noise-free frame: the renderer's colour and ideal depth.
  static slam::feature::FrameFeatures features_at(const Pose& camera_to_world, std::int64_t index) {
    const sim::render::RenderedView view = renderer_->render(camera_to_world);
    RgbdFrame frame;
    frame.index = index;
    frame.rgb = view.color_bgr;
    frame.depth_m = view.depth_m;
    const slam::feature::OrbFeatureExtractor extractor(slam::feature::FeatureOptions{},
                                                       scene_->sensors.camera.intrinsics);
    return extractor.extract(frame);
  }

  static Pose camera(double x_m, double y_m, double yaw_deg) {
    return camera_pose_from_planar(x_m, y_m, yaw_deg * std::numbers::pi / 180.0,
                                   scene_->sensors.camera.height_m);
  }

  static sim::scene::Scene* scene_;
  static sim::world::World* world_;
  static sim::render::RgbdRenderer* renderer_;
};

sim::scene::Scene* RenderedWorld::scene_ = nullptr;
sim::world::World* RenderedWorld::world_ = nullptr;
sim::render::RgbdRenderer* RenderedWorld::renderer_ = nullptr;

TEST_F(RenderedWorld, RecoversKnownRelativePoseToOneCentimetreAndHalfADegree) {
  // Along the south corridor, 0.3 m forward with a 6 degree turn and a small sideways step.
  const Pose a = camera(1.5, 0.1, 2.0);
  const Pose b = camera(1.8, -0.05, 8.0);
  const slam::feature::FrameFeatures fa = features_at(a, 0);
  const slam::feature::FrameFeatures fb = features_at(b, 1);
  ASSERT_GT(fa.depth_count(), 100u);
  slam::util::Instrumentation instrumentation;
  const slam::solve::VisualTransformation t = slam::solve::estimate_visual_transformation(
      fa, fb, scene_->sensors.camera.intrinsics, slam::solve::VisualTransformOptions{},
      instrumentation);
  ASSERT_TRUE(t.accepted) << "matches " << t.matches << " inliers " << t.inliers;
  const Pose truth = a.inverse() * b;
  const double translation_error_m = translation_distance_m(t.a_from_b, truth);
  const double rotation_error_deg =
      rotation_angle_rad(t.a_from_b, truth) * 180.0 / std::numbers::pi;
  std::printf("inliers %d of %d matches, error %.2f mm / %.3f deg, rms %.2f px\n", t.inliers,
              t.matches, translation_error_m * 1000, rotation_error_deg, t.rms_reprojection_px);
  EXPECT_LT(translation_error_m, 0.01);
  EXPECT_LT(rotation_error_deg, 0.5);
  EXPECT_GE(t.inliers, 20);
  // The information matrix is a usable (positive definite) weight.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(t.information);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
  EXPECT_EQ(instrumentation.counter(slam::counter::kRansacRuns), 1);
}

TEST_F(RenderedWorld, RejectsPairWithNoOverlap) {
  // South corridor looking east versus north corridor looking west: no surface in common.
  const slam::feature::FrameFeatures fa = features_at(camera(1.5, 0.0, 0.0), 0);
  const slam::feature::FrameFeatures fb = features_at(camera(6.5, 6.0, 180.0), 1);
  slam::util::Instrumentation instrumentation;
  const slam::solve::VisualTransformation t = slam::solve::estimate_visual_transformation(
      fa, fb, scene_->sensors.camera.intrinsics, slam::solve::VisualTransformOptions{},
      instrumentation);
  std::printf("no-overlap pair: %d matches, %d inliers\n", t.matches, t.inliers);
  EXPECT_FALSE(t.accepted);
}

TEST_F(RenderedWorld, TransformationIsDeterministic) {
  const slam::feature::FrameFeatures fa = features_at(camera(2.0, 0.0, 0.0), 0);
  const slam::feature::FrameFeatures fb = features_at(camera(2.3, 0.0, 4.0), 1);
  slam::util::Instrumentation instrumentation;
  const auto t1 = slam::solve::estimate_visual_transformation(
      fa, fb, scene_->sensors.camera.intrinsics, slam::solve::VisualTransformOptions{},
      instrumentation);
  const auto t2 = slam::solve::estimate_visual_transformation(
      fa, fb, scene_->sensors.camera.intrinsics, slam::solve::VisualTransformOptions{},
      instrumentation);
  ASSERT_TRUE(t1.accepted);
  EXPECT_EQ(t1.inliers, t2.inliers);
  EXPECT_TRUE(t1.a_from_b.matrix() == t2.a_from_b.matrix());
}

}  // namespace
}  // namespace wifislam
