#include "sim/robot/imu_model.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "core/error.hpp"
#include "sim/robot/sensor_schedule.hpp"

namespace wifislam::sim::robot {

namespace {

Eigen::Matrix3d yaw_rotation(double yaw_rad) {
  return Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

}  // namespace

ImuModel::ImuModel(const MotionProfile& motion, const scene::ImuSpec& spec, std::uint64_t seed)
    : motion_(motion), spec_(spec), rng_(Rng::stream(seed, "robot/imu")) {
  if (!(spec.rate_hz > 0.0) || !std::isfinite(spec.rate_hz)) {
    throw InvalidInputError(
        fmt::format("sensors.imu.rate_hz: {} is not a positive rate", spec.rate_hz));
  }
  // Whole microseconds, as every sensor clock here (tick_time); at least one.
  period_ns_ = std::max<std::int64_t>(1000, std::llround(1e6 / spec.rate_hz) * 1000);
}

Pose ImuModel::imu_in_base() const {
  Pose p = Pose::Identity();
  p.translation() = spec_.position_m;
  return p;
}

Timestamp ImuModel::sample_time(std::int64_t k) const { return tick_time(k, spec_.rate_hz); }

std::int64_t ImuModel::sample_count(Timestamp end) const { return tick_count(end, spec_.rate_hz); }

ImuState ImuModel::true_state(Timestamp t) const {
  const RobotState base = motion_.state_at(t);
  const Eigen::Matrix3d r_wb = yaw_rotation(base.heading_rad);
  const Eigen::Vector3d lever_w = r_wb * spec_.position_m;
  ImuState s;
  s.imu_to_world = Pose::Identity();
  s.imu_to_world.linear() = r_wb;  // the IMU's axes are the base's
  s.imu_to_world.translation() =
      Eigen::Vector3d(base.position_m.x(), base.position_m.y(), 0.0) + lever_w;
  // v_i = v_b + omega x r, omega = yaw rate about world z.
  s.velocity_mps = Eigen::Vector3d(base.velocity_mps.x(), base.velocity_mps.y(), 0.0) +
                   Eigen::Vector3d::UnitZ().cross(lever_w) * base.yaw_rate_radps;
  return s;
}

ImuReading ImuModel::ideal(std::int64_t k) const {
  // The interval since the previous sample (one period before the first): consecutive samples'
  // intervals tile the time line, so integrated velocities telescope exactly.
  const Timestamp t = sample_time(k);
  const Timestamp t0 = k > 0 ? sample_time(k - 1) : Timestamp::from_ns(t.ns - period_ns_);
  const double dt_s = static_cast<double>(t.ns - t0.ns) * 1e-9;
  const RobotState b0 = motion_.state_at(t0), b1 = motion_.state_at(t);
  // Heading is continuous; wrap the difference (far below pi in one sample).
  const double dyaw_rad = std::remainder(b1.heading_rad - b0.heading_rad, 2.0 * std::numbers::pi);
  const ImuState s0 = true_state(t0), s1 = true_state(t);
  const Eigen::Matrix3d r_mid = yaw_rotation(b0.heading_rad + 0.5 * dyaw_rad);
  const Eigen::Vector3d gravity_w(0.0, 0.0, -kStandardGravityMps2);
  ImuReading sample;
  sample.time = t;
  sample.angular_velocity_radps = Eigen::Vector3d(0.0, 0.0, dyaw_rad / dt_s);
  sample.specific_force_mps2 =
      r_mid.transpose() * ((s1.velocity_mps - s0.velocity_mps) / dt_s - gravity_w);
  return sample;
}

ImuReading ImuModel::measure(std::int64_t k) {
  if (k != next_k_) {
    throw std::logic_error(fmt::format("ImuModel::measure: sample {} after {}", k, next_k_ - 1));
  }
  ++next_k_;
  ImuReading sample = ideal(k);
  const double dt_s = static_cast<double>(period_ns_) * 1e-9;
  const double sqrt_dt = std::sqrt(dt_s);
  // Fixed draw order: bias steps (gyro xyz, accel xyz), then white noise (gyro, accel).
  for (int i = 0; i < 3; ++i)
    gyro_bias_[i] += spec_.gyroscope_random_walk * sqrt_dt * rng_.normal();
  for (int i = 0; i < 3; ++i)
    accel_bias_[i] += spec_.accelerometer_random_walk * sqrt_dt * rng_.normal();
  for (int i = 0; i < 3; ++i) {
    sample.angular_velocity_radps[i] +=
        gyro_bias_[i] + spec_.gyroscope_noise_density / sqrt_dt * rng_.normal();
  }
  for (int i = 0; i < 3; ++i) {
    sample.specific_force_mps2[i] +=
        accel_bias_[i] + spec_.accelerometer_noise_density / sqrt_dt * rng_.normal();
  }
  return sample;
}

}  // namespace wifislam::sim::robot
