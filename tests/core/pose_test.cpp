#include <gtest/gtest.h>

#include <cmath>

#include "core/camera_intrinsics.hpp"
#include "core/pose.hpp"

namespace wifislam {
namespace {

TEST(Pose, PlanarCameraLooksAlongItsYawWithYDown) {
  const Pose cam = camera_pose_from_planar(1.0, 2.0, M_PI / 2, 0.5);
  // Optical z (forward) points north, optical y (down) points to -z world, x right = east.
  EXPECT_TRUE(cam.linear().col(2).isApprox(Eigen::Vector3d(0, 1, 0), 1e-12));
  EXPECT_TRUE(cam.linear().col(1).isApprox(Eigen::Vector3d(0, 0, -1), 1e-12));
  EXPECT_TRUE(cam.linear().col(0).isApprox(Eigen::Vector3d(1, 0, 0), 1e-12));
  EXPECT_TRUE(cam.translation().isApprox(Eigen::Vector3d(1, 2, 0.5)));
  EXPECT_NEAR(camera_yaw_rad(cam), M_PI / 2, 1e-12);
}

TEST(Pose, PositivePitchLooksUp) {
  const Pose cam = camera_pose_from_planar(0, 0, 0, 0.5, 0.1);
  EXPECT_GT(cam.linear().col(2).z(), 0.09);
  EXPECT_NEAR(cam.linear().determinant(), 1.0, 1e-12);
}

TEST(Pose, DistancesAndAngles) {
  const Pose a = camera_pose_from_planar(0, 0, 0, 0.5), b = camera_pose_from_planar(3, 4, 0.3, 0.5);
  EXPECT_DOUBLE_EQ(translation_distance_m(a, b), 5.0);
  EXPECT_NEAR(rotation_angle_rad(a, b), 0.3, 1e-12);
}

TEST(CameraIntrinsics, KinectDefaultsAndBackProjection) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  EXPECT_EQ(k.width_px, 640);
  EXPECT_EQ(k.fx_px, 525.0);
  const Eigen::Vector3d p = k.back_project(319.5 + 52.5, 239.5, 2.0);
  EXPECT_TRUE(p.isApprox(Eigen::Vector3d(0.2, 0, 2.0)));
  EXPECT_NEAR(k.horizontal_fov_rad() * 180 / M_PI, 62.7, 0.1);
}

}  // namespace
}  // namespace wifislam
