#pragma once
// A 6-axis IMU rigidly mounted on the robot base (ImuSpec): angular velocity and specific force
// (gravity included: at rest it reads +9.80665 m/s^2 up) in the IMU frame.
//
// The signal comes from the motion profile's continuous motion, never from differenced poses:
// the profile gives the base's exact velocity and heading at any instant. Its speed and direction
// change in steps (constant speed between route points, pauses that start and end at once), so
// the true acceleration holds impulses that a point sample would miss. The sample stamped t_k is
// therefore the mean over (t_{k-1}, t_k], as an IMU that integrates between outputs
// (delta-angle, delta-velocity) reports it:
//   gyro  = R_bi^T z * (heading(t_k) - heading(t_k - dt)) / dt
//   accel = R_wi(mid)^T ((v_i(t_k) - v_i(t_k - dt)) / dt - g)
// with v_i the IMU's own velocity (base velocity plus the lever arm's turn), R_wi(mid) the IMU's
// orientation at mid-interval and g = (0, 0, -9.80665) m/s^2. Integrating these samples with the
// same convention (rotation by gyro * dt; velocity by (R_mid accel + g) dt) gives back the true
// velocity at every sample time, and the position to the integration rule's order.
//
// Noise, Kalibr's discrete model: each sample adds white noise of standard deviation
// noise_density / sqrt(dt) and a bias that performs a random walk, b_k = b_{k-1} + random_walk *
// sqrt(dt) * n, starting at zero. All draws come from the sub-stream "robot/imu" of the seed, six
// white and six bias draws per sample whatever the settings, so the stream stays aligned with
// time.

#include <cstdint>

#include <Eigen/Core>

#include "core/imu_csv.hpp"
#include "core/pose.hpp"
#include "core/rng.hpp"
#include "core/timestamp.hpp"
#include "sim/robot/motion_profile.hpp"
#include "sim/scene/scene.hpp"

namespace wifislam::sim::robot {

/// Standard gravity (m/s^2), the value Kalibr and the EuRoC tools use.
inline constexpr double kStandardGravityMps2 = 9.80665;

/// The IMU's true state: its frame in the world and its velocity (world frame).
struct ImuState {
  Pose imu_to_world = Pose::Identity();
  Eigen::Vector3d velocity_mps = Eigen::Vector3d::Zero();
};

class ImuModel {
 public:
  /// Throws InvalidInputError for a rate that is not positive.
  ImuModel(const MotionProfile& motion, const scene::ImuSpec& spec, std::uint64_t seed);

  /// The IMU frame in the robot base frame.
  Pose imu_in_base() const;
  /// Time of sample k (whole microseconds, as every sensor clock) and the number of samples up to
  /// `end` (inclusive).
  Timestamp sample_time(std::int64_t k) const;
  std::int64_t sample_count(Timestamp end) const;

  /// The noise-free sample k: the mean over (sample_time(k - 1), sample_time(k)] (the first:
  /// over the period before it).
  ImuReading ideal(std::int64_t k) const;
  /// The measured sample k (ideal plus bias and white noise). Call with k = 0, 1, 2, ... in order.
  ImuReading measure(std::int64_t k);

  ImuState true_state(Timestamp t) const;
  const scene::ImuSpec& spec() const { return spec_; }
  /// The biases after the last measure() (for tests and diagnostics).
  const Eigen::Vector3d& gyro_bias_radps() const { return gyro_bias_; }
  const Eigen::Vector3d& accel_bias_mps2() const { return accel_bias_; }

 private:
  const MotionProfile& motion_;
  scene::ImuSpec spec_;
  std::int64_t period_ns_ = 0;  // nominal sample period, whole microseconds
  Rng rng_;
  std::int64_t next_k_ = 0;
  Eigen::Vector3d gyro_bias_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_bias_ = Eigen::Vector3d::Zero();
};

}  // namespace wifislam::sim::robot
