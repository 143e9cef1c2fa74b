#include "sim/robot/wheel_odometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "sim/robot/sensor_schedule.hpp"
#include "tests/sim/robot/test_routes.hpp"

namespace wifislam::sim {
namespace {

struct OdometrySample {
  robot::RobotState truth;
  OdometryReading reading;
};

std::vector<OdometrySample> drive(const world::RoutePath& route, const scene::OdometrySpec& spec,
                                  std::uint64_t seed) {
  robot::RobotMotionOptions motion_options;
  motion_options.max_yaw_rate_radps = 1.0;
  motion_options.pause.spacing_min_m = 3.0;
  motion_options.pause.spacing_max_m = 4.0;
  motion_options.pause.duration_s = 2.0;
  const robot::MotionProfile motion(route, motion_options, seed);
  robot::SensorScheduleOptions schedule_options;
  schedule_options.odometry_rate_hz = spec.rate_hz;
  const robot::SensorSchedule schedule(motion, schedule_options);
  robot::WheelOdometry odometry(spec, seed);
  std::vector<OdometrySample> out;
  for (std::int64_t j = 0; j < schedule.odometry_count(); ++j) {
    const Timestamp t = schedule.odometry_time(j);
    const robot::RobotState truth = motion.state_at(t);
    out.push_back({truth, odometry.measure(t, truth)});
  }
  return out;
}

double yaw_of(const Pose& pose) { return std::atan2(pose.linear()(1, 0), pose.linear()(0, 0)); }

struct Stats {
  double mean = 0, stddev = 0;
};
Stats stats(const std::vector<double>& v) {
  Stats s;
  for (double x : v) s.mean += x;
  s.mean /= static_cast<double>(v.size());
  for (double x : v) s.stddev += (x - s.mean) * (x - s.mean);
  s.stddev = std::sqrt(s.stddev / static_cast<double>(v.size() - 1));
  return s;
}

// Splits the run into pieces of `piece` (metres or radians of true motion, per `key`) and returns
// for each piece (measured - true) of the same quantity.
template <class TrueKey, class MeasuredKey>
std::vector<double> piece_errors(const std::vector<OdometrySample>& samples, double piece,
                                 TrueKey true_key, MeasuredKey measured_key) {
  std::vector<double> errors;
  std::size_t from = 0;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    if (true_key(samples[from], samples[i]) >= piece) {
      errors.push_back(measured_key(samples[from], samples[i]) -
                       true_key(samples[from], samples[i]));
      from = i;
    }
  }
  return errors;
}

TEST(WheelOdometry, DriftOverALongStraightRunMatchesTheConfiguredNoise) {
  scene::OdometrySpec spec;  // noise 0.02 m per metre, scale error 1 %, yaw bias 0.002 rad/m
  const auto samples = drive(test::straight_route(3000.0), spec, 21);
  auto true_distance = [](const OdometrySample& a, const OdometrySample& b) {
    return b.truth.arc_length_m - a.truth.arc_length_m;
  };
  auto measured_distance = [](const OdometrySample& a, const OdometrySample& b) {
    return (b.reading.base_in_odom.translation() - a.reading.base_in_odom.translation()).norm();
  };
  const auto errors = piece_errors(samples, 1.0, true_distance, measured_distance);
  ASSERT_GT(errors.size(), 2900u);
  const Stats s = stats(errors);
  // Pieces are 1 m (to within one 50 Hz step of 1 cm), so the error std is noise_per_m and the
  // mean error is the scale error.
  EXPECT_NEAR(s.stddev, spec.noise_per_m, 0.15 * spec.noise_per_m);
  EXPECT_NEAR(s.mean, spec.scale_error, 0.15 * spec.scale_error);

  auto measured_heading_change = [](const OdometrySample& a, const OdometrySample& b) {
    return std::remainder(yaw_of(b.reading.base_in_odom) - yaw_of(a.reading.base_in_odom),
                          2 * std::numbers::pi);
  };
  auto zero = [](const OdometrySample&, const OdometrySample&) { return 0.0; };
  // Heading on a straight run: only the systematic bias, yaw_bias_radpm per metre.
  std::vector<double> heading_errors;
  std::size_t from = 0;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    if (true_distance(samples[from], samples[i]) >= 1.0) {
      heading_errors.push_back(measured_heading_change(samples[from], samples[i]) -
                               zero(samples[from], samples[i]));
      from = i;
    }
  }
  EXPECT_NEAR(stats(heading_errors).mean, spec.yaw_bias_radpm, 0.15 * spec.yaw_bias_radpm);
}

TEST(WheelOdometry, HeadingNoisePerRadianTurnedMatchesTheConfiguredNoise) {
  scene::OdometrySpec spec;
  spec.yaw_bias_radpm = 0.0;
  // Radius 1 m: one radian of turning per metre; 320 laps give ~2000 one-radian pieces.
  const auto samples = drive(test::circle_route(1.0, 320.0), spec, 5);
  auto true_turn = [](const OdometrySample& a, const OdometrySample& b) {
    return b.truth.arc_length_m - a.truth.arc_length_m;  // = radians on the unit circle
  };
  auto measured_turn = [](const OdometrySample& a, const OdometrySample& b) {
    return std::remainder(yaw_of(b.reading.base_in_odom) - yaw_of(a.reading.base_in_odom),
                          2 * std::numbers::pi);
  };
  const auto errors = piece_errors(samples, 1.0, true_turn, measured_turn);
  ASSERT_GT(errors.size(), 1900u);
  const Stats s = stats(errors);
  EXPECT_NEAR(s.stddev, spec.noise_per_rad, 0.15 * spec.noise_per_rad);
  EXPECT_NEAR(s.mean, 0.0,
              3.0 * spec.noise_per_rad / std::sqrt(static_cast<double>(errors.size())));
}

TEST(WheelOdometry, StandingStillAddsNoDrift) {
  const auto samples = drive(test::straight_route(20.0), scene::OdometrySpec{}, 9);
  int paused_pairs = 0;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    if (samples[i - 1].truth.paused() && samples[i].truth.paused() &&
        samples[i - 1].truth.pause_index == samples[i].truth.pause_index) {
      EXPECT_TRUE(
          samples[i].reading.base_in_odom.isApprox(samples[i - 1].reading.base_in_odom, 0.0));
      ++paused_pairs;
    }
  }
  EXPECT_GT(paused_pairs, 100);
  // The odometry frame starts at the first base pose.
  EXPECT_TRUE(samples.front().reading.base_in_odom.isApprox(Pose::Identity()));
}

TEST(WheelOdometry, SameSeedSameReadingsOtherSeedOtherDrift) {
  const auto a = drive(test::straight_route(20.0), scene::OdometrySpec{}, 9);
  const auto b = drive(test::straight_route(20.0), scene::OdometrySpec{}, 9);
  const auto c = drive(test::straight_route(20.0), scene::OdometrySpec{}, 10);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_TRUE(a.back().reading.base_in_odom.isApprox(b.back().reading.base_in_odom, 0.0));
  EXPECT_FALSE(a.back().reading.base_in_odom.isApprox(c.back().reading.base_in_odom, 1e-9));
}

TEST(WheelOdometry, NoiseFreeOdometryFollowsTheTruth) {
  scene::OdometrySpec exact;
  exact.noise_per_m = exact.noise_per_rad = exact.scale_error = exact.yaw_bias_radpm = 0.0;
  const auto samples = drive(test::rounded_rectangle_route(10.0, 6.0, 0.6), exact, 3);
  const Pose start = samples.front().truth.base_to_world();
  for (const auto& s : samples) {
    const Pose truth_in_start = start.inverse() * s.truth.base_to_world();
    EXPECT_LT((truth_in_start.translation() - s.reading.base_in_odom.translation()).norm(), 0.01);
  }
}

}  // namespace
}  // namespace wifislam::sim
