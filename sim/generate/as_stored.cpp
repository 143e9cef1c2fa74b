#include "sim/generate/as_stored.hpp"

#include "core/tum_trajectory.hpp"
#include "sim/render/depth_png.hpp"

namespace wifislam::sim::generate {

cv::Mat depth_as_stored(const cv::Mat& depth_units) { return depth_from_png_units(depth_units); }

OdometryReading odometry_as_stored(const OdometryReading& reading) {
  return {reading.time, StampedPose::from_pose(reading.time, reading.base_in_odom).pose()};
}

}  // namespace wifislam::sim::generate
