// The simulated IMU (sim/robot/imu_model.hpp): integrating its noise-free samples from a true state
// gives back the ground truth over a route with turns, pauses and a turn on the spot (velocity and
// heading exactly, position to the integration rule's first order in the sample period); at rest
// its Allan deviation recovers the configured white-noise densities and bias random walks; the
// noise is the seed's own stream.
#include "sim/robot/imu_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "sim/robot/sensor_schedule.hpp"
#include "tests/sim/robot/test_routes.hpp"

namespace wifislam::sim {
namespace {

robot::RobotMotionOptions walk_with_short_pauses() {
  robot::RobotMotionOptions o;
  o.speed_mps = 0.5;
  o.max_yaw_rate_radps = 0.6;
  o.pause.spacing_min_m = 3.0;
  o.pause.spacing_max_m = 4.0;
  o.pause.duration_s = 2.0;
  return o;
}

scene::ImuSpec noise_free(double rate_hz) {
  scene::ImuSpec spec;
  spec.rate_hz = rate_hz;
  spec.position_m = {0.12, -0.05, 0.3};  // a lever arm, so turning moves the IMU too
  spec.gyroscope_noise_density = spec.gyroscope_random_walk = 0.0;
  spec.accelerometer_noise_density = spec.accelerometer_random_walk = 0.0;
  return spec;
}

struct IntegrationError {
  double position_m = 0.0, velocity_mps = 0.0, rotation_rad = 0.0;
};

/// Integrates every sample after the first from the true state at the first sample's time:
/// rotation by gyro * dt, velocity by (R_mid accel + g) dt, position by the trapezoid rule; the
/// largest errors against the true state at every sample time.
IntegrationError integrate(const robot::MotionProfile& motion, const scene::ImuSpec& spec) {
  const robot::ImuModel imu(motion, spec, 11);
  const std::int64_t n = imu.sample_count(motion.end_time());
  robot::ImuState start = imu.true_state(imu.sample_time(0));
  Eigen::Matrix3d r = start.imu_to_world.linear();
  Eigen::Vector3d v = start.velocity_mps, p = start.imu_to_world.translation();
  const Eigen::Vector3d g(0.0, 0.0, -robot::kStandardGravityMps2);
  IntegrationError e;
  for (std::int64_t k = 1; k < n; ++k) {
    const ImuReading s = imu.ideal(k);
    const double dt = static_cast<double>(imu.sample_time(k).ns - imu.sample_time(k - 1).ns) * 1e-9;
    const Eigen::Vector3d w = s.angular_velocity_radps;
    const auto exp = [&](double h) {
      const double angle = w.norm() * h;
      return angle > 0.0 ? Eigen::AngleAxisd(angle, w.normalized()).toRotationMatrix()
                         : Eigen::Matrix3d::Identity();
    };
    const Eigen::Matrix3d r_mid = r * exp(0.5 * dt);
    const Eigen::Vector3d v_next = v + (r_mid * s.specific_force_mps2 + g) * dt;
    p += 0.5 * (v + v_next) * dt;
    v = v_next;
    r = r * exp(dt);
    const robot::ImuState truth = imu.true_state(s.time);
    e.position_m = std::max(e.position_m, (p - truth.imu_to_world.translation()).norm());
    e.velocity_mps = std::max(e.velocity_mps, (v - truth.velocity_mps).norm());
    e.rotation_rad = std::max(
        e.rotation_rad, Eigen::AngleAxisd(r.transpose() * truth.imu_to_world.linear()).angle());
  }
  return e;
}

TEST(ImuModel, IntegratingTheNoiseFreeImuReproducesGroundTruthToTheIntegratorsOrder) {
  for (const world::RoutePath& route :
       {test::rounded_rectangle_route(12.0, 8.0, 0.6), test::there_and_back_route(6.0)}) {
    const robot::MotionProfile motion(route, walk_with_short_pauses(), 7);
    const IntegrationError at200 = integrate(motion, noise_free(200.0));
    const IntegrationError at800 = integrate(motion, noise_free(800.0));
    // Velocity and heading telescope: exact up to rounding, whatever the rate.
    EXPECT_LT(at200.velocity_mps, 1e-9);
    EXPECT_LT(at200.rotation_rad, 1e-9);
    // Position: the trapezoid rule's error at the speed steps, first order in the period.
    EXPECT_LT(at200.position_m, 0.01) << "over " << motion.length_m() << " m";
    EXPECT_GT(at200.position_m, 0.0);
    std::printf("%.1f m: position error %.3g m at 200 Hz, %.3g m at 800 Hz\n", motion.length_m(),
                at200.position_m, at800.position_m);
    EXPECT_LT(at800.position_m, at200.position_m / 3.0)
        << at200.position_m << " m at 200 Hz, " << at800.position_m << " m at 800 Hz";
  }
}

TEST(ImuModel, AtRestItReadsGravityUpAndNoRotation) {
  const robot::MotionProfile motion(test::straight_route(2.0), walk_with_short_pauses(), 7);
  robot::ImuModel imu(motion, noise_free(200.0), 3);
  const ImuReading r = imu.measure(0);  // the robot stands at the start
  EXPECT_NEAR(r.specific_force_mps2.z(), robot::kStandardGravityMps2, 1e-12);
  EXPECT_NEAR(r.specific_force_mps2.head<2>().norm(), 0.0, 1e-12);
  EXPECT_NEAR(r.angular_velocity_radps.norm(), 0.0, 1e-12);
}

/// The integral of samples `y` (period dt) up to each sample: theta[i] = dt * (y[0] + ... +
/// y[i - 1]).
std::vector<double> integrated(const std::vector<double>& y, double dt) {
  std::vector<double> theta(y.size() + 1, 0.0);
  for (std::size_t i = 0; i < y.size(); ++i) theta[i + 1] = theta[i] + y[i] * dt;
  return theta;
}

/// Overlapping Allan variance at cluster size m, from the integrated samples.
double allan_variance(const std::vector<double>& theta, double dt, std::size_t m) {
  const double tau = static_cast<double>(m) * dt;
  double sum = 0.0;
  const std::size_t count = theta.size() - 2 * m;
  for (std::size_t k = 0; k < count; ++k) {
    const double d = theta[k + 2 * m] - 2.0 * theta[k + m] + theta[k];
    sum += d * d;
  }
  return sum / (2.0 * tau * tau * static_cast<double>(count));
}

/// Fits sigma^2(tau) = N^2 / tau + K^2 tau / 3 to the Allan variance (averaged over the three
/// axes) at log-spaced tau, weighting each point by the inverse of its variance; returns {N, K}.
std::pair<double, double> fit_allan(const std::vector<std::vector<double>>& samples, double dt) {
  std::vector<std::vector<double>> axes;
  for (const auto& y : samples) axes.push_back(integrated(y, dt));
  double a11 = 0, a12 = 0, a22 = 0, b1 = 0, b2 = 0;
  const std::size_t n = samples[0].size();
  for (double m_real = 1.0; m_real < static_cast<double>(n) / 10.0; m_real *= 1.5) {
    const std::size_t m = static_cast<std::size_t>(m_real);
    const double tau = static_cast<double>(m) * dt;
    double avar = 0.0;
    for (const auto& axis : axes) avar += allan_variance(axis, dt, m) / 3.0;
    // An Allan variance over T seconds at tau has a relative variance of about tau / T.
    const double x1 = 1.0 / tau, x2 = tau / 3.0, w = 1.0 / (avar * avar * tau);
    a11 += w * x1 * x1;
    a12 += w * x1 * x2;
    a22 += w * x2 * x2;
    b1 += w * x1 * avar;
    b2 += w * x2 * avar;
  }
  const double det = a11 * a22 - a12 * a12;
  const double n2 = (b1 * a22 - b2 * a12) / det, k2 = (a11 * b2 - a12 * b1) / det;
  return {std::sqrt(n2), std::sqrt(k2)};
}

TEST(ImuModel, AllanDeviationAtRestRecoversTheConfiguredNoise) {
  // The robot stands through its first pause: 6 hours at rest, long enough to see the gyro's
  // bias walk (its Allan deviation turns up after ~15 s) over more than 1000 of its crossings.
  robot::RobotMotionOptions options = walk_with_short_pauses();
  options.pause.duration_s = 6 * 3600.0;
  const robot::MotionProfile motion(test::straight_route(1.0), options, 7);
  const scene::ImuSpec spec;  // the defaults: EuRoC's ADIS16448
  robot::ImuModel imu(motion, spec, 11);
  const double dt = 1.0 / spec.rate_hz;
  const std::int64_t n = imu.sample_count(motion.pauses().front().end) - 1;
  std::vector<std::vector<double>> gyro(3), accel(3);
  for (int i = 0; i < 3; ++i) {
    gyro[i].reserve(n);
    accel[i].reserve(n);
  }
  for (std::int64_t k = 0; k < n; ++k) {
    const ImuReading r = imu.measure(k);
    for (int i = 0; i < 3; ++i) {
      gyro[i].push_back(r.angular_velocity_radps[i]);
      accel[i].push_back(r.specific_force_mps2[i]);
    }
  }
  const auto [gyro_n, gyro_k] = fit_allan(gyro, dt);
  const auto [accel_n, accel_k] = fit_allan(accel, dt);
  EXPECT_NEAR(gyro_n / spec.gyroscope_noise_density, 1.0, 0.1) << gyro_n;
  EXPECT_NEAR(gyro_k / spec.gyroscope_random_walk, 1.0, 0.1) << gyro_k;
  EXPECT_NEAR(accel_n / spec.accelerometer_noise_density, 1.0, 0.1) << accel_n;
  EXPECT_NEAR(accel_k / spec.accelerometer_random_walk, 1.0, 0.1) << accel_k;
  std::printf("gyro N %.4g (%.4g) K %.4g (%.4g); accel N %.4g (%.4g) K %.4g (%.4g)\n", gyro_n,
              spec.gyroscope_noise_density, gyro_k, spec.gyroscope_random_walk, accel_n,
              spec.accelerometer_noise_density, accel_k, spec.accelerometer_random_walk);
}

TEST(ImuModel, NoiseComesFromTheSeedsOwnStream) {
  const robot::MotionProfile motion(test::straight_route(3.0), walk_with_short_pauses(), 7);
  const scene::ImuSpec spec;
  robot::ImuModel a(motion, spec, 5), b(motion, spec, 5), c(motion, spec, 6);
  for (std::int64_t k = 0; k < 50; ++k) {
    const ImuReading ra = a.measure(k), rb = b.measure(k), rc = c.measure(k);
    EXPECT_EQ(ra.specific_force_mps2, rb.specific_force_mps2);
    EXPECT_EQ(ra.angular_velocity_radps, rb.angular_velocity_radps);
    EXPECT_NE(ra.specific_force_mps2, rc.specific_force_mps2);
  }
}

}  // namespace
}  // namespace wifislam::sim
