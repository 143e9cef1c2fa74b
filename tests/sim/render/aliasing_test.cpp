// The scene's aliasing knob shows in the images: two different wall segments with the shared
// look (aliasing 1.0) give many geometrically consistent ORB matches; with looks of their own
// (aliasing 0.0) they give few.

#include <gtest/gtest.h>

#include <numbers>

#include <opencv2/calib3d.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/pose.hpp"
#include "sim/render/rgbd_renderer.hpp"
#include "tests/sim/render/test_meshes.hpp"

namespace wifislam::sim {
namespace {

// RANSAC-consistent ORB matches between two images (Lowe ratio 0.8, fundamental matrix, 3 px).
int consistent_orb_matches(const cv::Mat& a_bgr, const cv::Mat& b_bgr) {
  cv::Ptr<cv::ORB> orb = cv::ORB::create(1000);
  std::vector<cv::KeyPoint> ka, kb;
  cv::Mat da, db, ga, gb;
  cv::cvtColor(a_bgr, ga, cv::COLOR_BGR2GRAY);
  cv::cvtColor(b_bgr, gb, cv::COLOR_BGR2GRAY);
  orb->detectAndCompute(ga, cv::noArray(), ka, da);
  orb->detectAndCompute(gb, cv::noArray(), kb, db);
  if (ka.size() < 8 || kb.size() < 8) return 0;
  cv::BFMatcher matcher(cv::NORM_HAMMING);
  std::vector<std::vector<cv::DMatch>> knn;
  matcher.knnMatch(da, db, knn, 2);
  std::vector<cv::Point2f> pa, pb;
  for (const auto& m : knn) {
    if (m.size() == 2 && m[0].distance < 0.8f * m[1].distance) {
      pa.push_back(ka[m[0].queryIdx].pt);
      pb.push_back(kb[m[0].trainIdx].pt);
    }
  }
  if (pa.size() < 8) return 0;
  std::vector<unsigned char> inliers;
  cv::findFundamentalMat(pa, pb, cv::FM_RANSAC, 3.0, 0.99, inliers);
  return cv::countNonZero(inliers);
}

int matches_between_segments(int variant_a, int variant_b) {
  const test::HandCorridor wall = test::two_segment_wall(variant_a, variant_b);
  render::RgbdRenderer renderer(CameraIntrinsics::kinect_v1());
  renderer.set_world(wall.mesh, wall.lights, 2024, scene::AppearanceThemes{});
  // The same place relative to each 4 m segment, 1.6 m from the wall, looking at it.
  const double yaw = std::numbers::pi / 2;
  const cv::Mat a = renderer.render(camera_pose_from_planar(1.9, -0.6, yaw, 1.2)).color_bgr;
  const cv::Mat b = renderer.render(camera_pose_from_planar(5.9, -0.6, yaw, 1.2)).color_bgr;
  return consistent_orb_matches(a, b);
}

TEST(AliasingKnob, SharedLookSegmentsMatchFarMoreThanUniqueOnes) {
  const int shared = matches_between_segments(0, 0);  // aliasing 1.0: both use the shared look
  const int unique = matches_between_segments(1, 2);  // aliasing 0.0: each its own look
  std::printf("RANSAC-consistent ORB matches: shared look %d, unique looks %d\n", shared, unique);
  EXPECT_GE(shared, 150);
  EXPECT_GE(shared, 4 * std::max(unique, 10));
}

}  // namespace
}  // namespace wifislam::sim
