#pragma once
// Simulated wheel odometry (what a TurtleBot base reports): the robot base's pose in an odometry
// frame that starts at the base's first pose and drifts away from the truth.
//
// Between two readings the true motion is a distance d travelled along the route and a heading
// change dtheta. The odometry integrates the measured
//   d'      = d (1 + scale_error) + noise_per_m   * sqrt(d)        * n1
//   dtheta' = dtheta + yaw_bias_radpm * d + noise_per_rad * sqrt(|dtheta|) * n2
// with n1, n2 standard normal from the sub-stream "odometry" of the seed. The noise variance
// grows linearly with distance and angle, so after D metres (or R radians) the random part of the
// error has standard deviation noise_per_m * sqrt(D) (noise_per_rad * sqrt(R)) whatever the
// reading rate: `noise_per_m` is the error after one metre. Standing still adds no error.
// Integration uses the midpoint heading (exact for arcs of constant curvature to second order).

#include <cstdint>
#include <optional>

#include "core/rng.hpp"
#include "core/sensor_stream.hpp"
#include "sim/robot/motion_profile.hpp"
#include "sim/scene/scene.hpp"

namespace wifislam::sim::robot {

class WheelOdometry {
 public:
  WheelOdometry(const scene::OdometrySpec& spec, std::uint64_t seed);

  /// The reading at time `t`, given the true robot state then. Call with non-decreasing times;
  /// the first call defines the odometry frame (identity at the first state).
  OdometryReading measure(Timestamp t, const RobotState& truth);

  const scene::OdometrySpec& spec() const { return spec_; }

 private:
  scene::OdometrySpec spec_;
  Rng rng_;
  std::optional<RobotState> previous_truth_;
  double x_m_ = 0.0, y_m_ = 0.0, theta_rad_ = 0.0;
};

}  // namespace wifislam::sim::robot
