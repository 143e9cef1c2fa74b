#include "sim/robot/wheel_odometry.hpp"

#include <cmath>
#include <numbers>

namespace wifislam::sim::robot {

WheelOdometry::WheelOdometry(const scene::OdometrySpec& spec, std::uint64_t seed)
    : spec_(spec), rng_(Rng::stream(seed, "odometry")) {}

OdometryReading WheelOdometry::measure(Timestamp t, const RobotState& truth) {
  if (previous_truth_) {
    const double d_m = std::abs(truth.arc_length_m - previous_truth_->arc_length_m);
    const double dtheta_rad =
        std::remainder(truth.heading_rad - previous_truth_->heading_rad, 2.0 * std::numbers::pi);
    // Two draws per reading whatever the motion, so the stream stays aligned with time.
    const double n1 = rng_.normal(), n2 = rng_.normal();
    const double d_meas = d_m * (1.0 + spec_.scale_error) + spec_.noise_per_m * std::sqrt(d_m) * n1;
    const double dtheta_meas = dtheta_rad + spec_.yaw_bias_radpm * d_m +
                               spec_.noise_per_rad * std::sqrt(std::abs(dtheta_rad)) * n2;
    const double mid = theta_rad_ + 0.5 * dtheta_meas;
    x_m_ += d_meas * std::cos(mid);
    y_m_ += d_meas * std::sin(mid);
    theta_rad_ = std::remainder(theta_rad_ + dtheta_meas, 2.0 * std::numbers::pi);
  }
  previous_truth_ = truth;
  OdometryReading reading;
  reading.time = t;
  reading.base_in_odom = Pose::Identity();
  reading.base_in_odom.linear() =
      Eigen::AngleAxisd(theta_rad_, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  reading.base_in_odom.translation() = Eigen::Vector3d(x_m_, y_m_, 0.0);
  return reading;
}

}  // namespace wifislam::sim::robot
