// RTAB-Map's node schedule: at most one node per 1 / Rtabmap/DetectionRate, and only after
// RGBD/LinearUpdate or RGBD/AngularUpdate of motion.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "slam/frontend/keyframe_schedule.hpp"

namespace wifislam::slam {
namespace {

constexpr std::int64_t kSecondNs = 1'000'000'000;

Pose moved(double x_m, double yaw_rad) {
  Pose p = Pose::Identity();
  p.translation().x() = x_m;
  p.linear() = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitY()).toRotationMatrix();
  return p;
}

TEST(KeyframeSchedule, NeedsBothThePeriodAndEnoughMotion) {
  const frontend::KeyframeSchedule rtabmap;                     // 1 Hz, 0.1 m, 0.1 rad
  EXPECT_FALSE(rtabmap.due(kSecondNs / 2, moved(1.0, 0.0)));    // moved, too soon
  EXPECT_FALSE(rtabmap.due(5 * kSecondNs, moved(0.05, 0.05)));  // time, standing still
  EXPECT_TRUE(rtabmap.due(kSecondNs, moved(0.12, 0.0)));
  EXPECT_TRUE(rtabmap.due(2 * kSecondNs, moved(0.0, 0.12)));  // turning in place counts
}

TEST(KeyframeSchedule, APeriodOfWholeFramesIsMetAtThatFrame) {
  // 3 fps: frame times are k / 3 s rounded to the nanosecond; the third frame is 1 s later.
  const frontend::KeyframeSchedule rtabmap;
  EXPECT_TRUE(rtabmap.due(999'999'999, moved(0.5, 0.0)));
  EXPECT_FALSE(rtabmap.due(666'666'667, moved(0.5, 0.0)));
  // A rate of 0 (RTAB-Map: as fast as frames come) leaves only the motion bounds.
  const frontend::KeyframeSchedule every_frame{0.0, 0.1, 0.1};
  EXPECT_TRUE(every_frame.due(1, moved(0.2, 0.0)));
}

}  // namespace
}  // namespace wifislam::slam
