#include "sim/robot/motion_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "sim/robot/camera_mount.hpp"
#include "tests/sim/robot/test_routes.hpp"

namespace wifislam::sim {
namespace {

robot::RobotMotionOptions default_options() {
  robot::RobotMotionOptions o;
  o.speed_mps = 0.5;
  o.max_yaw_rate_radps = 0.6;
  o.pause.spacing_min_m = 3.0;
  o.pause.spacing_max_m = 4.0;
  o.pause.duration_s = 10.0;
  return o;
}

Timestamp at_s(double s) { return Timestamp::from_seconds(s); }

TEST(MotionProfile, PausesAreSpacedWithinTheSceneRange) {
  const world::RoutePath route = test::rounded_rectangle_route(20.0, 12.0, 0.6);
  const robot::MotionProfile motion(route, default_options(), 7);
  const auto& pauses = motion.pauses();
  ASSERT_GT(pauses.size(), 10u);
  EXPECT_EQ(pauses.front().arc_length_m, 0.0);  // the robot scans before it sets off
  double min_gap = 1e9, max_gap = 0.0;
  for (std::size_t i = 1; i < pauses.size(); ++i) {
    const double gap = pauses[i].arc_length_m - pauses[i - 1].arc_length_m;
    EXPECT_GE(gap, 3.0);
    EXPECT_LE(gap, 4.0);
    min_gap = std::min(min_gap, gap);
    max_gap = std::max(max_gap, gap);
  }
  // Drawn per pause, not one fixed spacing.
  EXPECT_GT(max_gap - min_gap, 0.3);
  // No room for one more pause at the end.
  EXPECT_LT(motion.length_m() - pauses.back().arc_length_m, 4.0);
}

TEST(MotionProfile, PauseSpacingDependsOnTheSeedOnly) {
  const world::RoutePath route = test::rounded_rectangle_route(20.0, 12.0, 0.6);
  const robot::MotionProfile a(route, default_options(), 7), b(route, default_options(), 7),
      c(route, default_options(), 8);
  ASSERT_EQ(a.pauses().size(), b.pauses().size());
  for (std::size_t i = 0; i < a.pauses().size(); ++i) {
    EXPECT_EQ(a.pauses()[i].arc_length_m, b.pauses()[i].arc_length_m);
    EXPECT_EQ(a.pauses()[i].start, b.pauses()[i].start);
  }
  EXPECT_NE(a.pauses()[1].arc_length_m, c.pauses()[1].arc_length_m);
  // A faster robot pauses at the same places.
  robot::RobotMotionOptions fast = default_options();
  fast.speed_mps = 1.0;
  const robot::MotionProfile d(route, fast, 7);
  ASSERT_EQ(a.pauses().size(), d.pauses().size());
  for (std::size_t i = 0; i < a.pauses().size(); ++i)
    EXPECT_EQ(a.pauses()[i].arc_length_m, d.pauses()[i].arc_length_m);
}

TEST(MotionProfile, PausesLastTheConfiguredDurationWithZeroMotion) {
  const world::RoutePath route = test::rounded_rectangle_route(20.0, 12.0, 0.6);
  const robot::MotionProfile motion(route, default_options(), 3);
  for (std::size_t p = 0; p < motion.pauses().size(); ++p) {
    const robot::RobotPause& pause = motion.pauses()[p];
    EXPECT_NEAR((pause.end.ns - pause.start.ns) * 1e-9, 10.0, 1e-6);
    EXPECT_EQ(pause.start.ns % 1000, 0);  // whole microseconds
    const robot::RobotState first = motion.state_at(pause.start);
    EXPECT_TRUE(first.paused());
    EXPECT_EQ(first.pause_index, static_cast<int>(p));
    for (int k = 0; k <= 100; ++k) {
      const Timestamp t =
          Timestamp::from_ns(pause.start.ns + (pause.end.ns - pause.start.ns) * k / 100);
      const robot::RobotState s = motion.state_at(t);
      EXPECT_EQ(s.position_m, first.position_m);
      EXPECT_EQ(s.heading_rad, first.heading_rad);
      if (k < 100) {  // the pause is [start, end): at `end` the robot sets off
        EXPECT_EQ(s.speed_mps, 0.0);
        EXPECT_EQ(s.yaw_rate_radps, 0.0);
        EXPECT_EQ(s.pause_index, static_cast<int>(p));
      }
    }
    EXPECT_LT((first.position_m - pause.position_m).norm(), 1e-12);
    // Just before and just after, it moves (except before the first pause at t = 0).
    if (p > 0) {
      EXPECT_GT(motion.state_at(Timestamp::from_ns(pause.start.ns - 1000)).speed_mps, 0.0);
    }
    EXPECT_GT(motion.state_at(Timestamp::from_ns(pause.end.ns + 1000)).speed_mps, 0.0);
  }
}

TEST(MotionProfile, TurnsSlowTheRobotSoTheYawRateStaysBounded) {
  const world::RoutePath route = test::rounded_rectangle_route(10.0, 8.0, 0.6);
  robot::RobotMotionOptions options = default_options();
  options.pause.duration_s = 0.0;
  const robot::MotionProfile motion(route, options, 1);
  double max_yaw_rate = 0.0, min_speed = 1e9, max_speed = 0.0;
  robot::RobotState prev = motion.state_at(Timestamp{0});
  const std::int64_t step_ns = 5'000'000;
  for (std::int64_t ns = step_ns; ns <= motion.end_time().ns; ns += step_ns) {
    const robot::RobotState s = motion.state_at(Timestamp::from_ns(ns));
    const double dh = std::remainder(s.heading_rad - prev.heading_rad, 2 * std::numbers::pi);
    max_yaw_rate = std::max(max_yaw_rate, std::abs(dh) / (step_ns * 1e-9));
    // Continuous motion: never faster than the cruise speed between samples.
    EXPECT_LE((s.position_m - prev.position_m).norm(), 0.5 * step_ns * 1e-9 * 1.0001 + 1e-9);
    EXPECT_LE(std::abs(s.yaw_rate_radps), 0.6 * 1.001);
    if (s.speed_mps > 0) {
      min_speed = std::min(min_speed, s.speed_mps);
      max_speed = std::max(max_speed, s.speed_mps);
    }
    prev = s;
  }
  EXPECT_LE(max_yaw_rate, 0.6 * 1.01);
  EXPECT_GT(max_yaw_rate, 0.55);            // turns do reach the bound
  EXPECT_NEAR(max_speed, 0.5, 1e-3);        // straight parts at cruise speed
  EXPECT_NEAR(min_speed, 0.6 * 0.6, 0.02);  // v = yaw_rate_max * radius in the corners
}

TEST(MotionProfile, StraightRunTakesLengthOverSpeedPlusPauses) {
  const world::RoutePath route = test::straight_route(50.0);
  const robot::MotionProfile motion(route, default_options(), 11);
  const double expected = 50.0 / 0.5 + 10.0 * static_cast<double>(motion.pauses().size());
  EXPECT_NEAR(motion.end_time().seconds(), expected, 1e-4);
  EXPECT_NEAR(motion.moving_time_s(), 100.0, 1e-4);
  const robot::RobotState end = motion.state_at(motion.end_time());
  EXPECT_NEAR(end.position_m.x(), 50.0, 1e-9);
  EXPECT_NEAR(end.arc_length_m, 50.0, 1e-9);
}

TEST(MotionProfile, GroundTruthIsAPureFunctionOfTime) {
  const world::RoutePath route = test::rounded_rectangle_route(20.0, 12.0, 0.6);
  const robot::MotionProfile motion(route, default_options(), 5);
  std::vector<robot::RobotState> forward;
  for (int k = 0; k < 2000; ++k) forward.push_back(motion.state_at(at_s(k * 0.0731)));
  for (int k = 1999; k >= 0; k -= 7) {
    const robot::RobotState s = motion.state_at(at_s(k * 0.0731));
    EXPECT_EQ(s.position_m, forward[k].position_m);
    EXPECT_EQ(s.heading_rad, forward[k].heading_rad);
  }
}

TEST(MotionProfile, CameraSitsAtTheMountHeightLookingAlongTheHeading) {
  const world::RoutePath route = test::rounded_rectangle_route(20.0, 12.0, 0.6);
  const robot::MotionProfile motion(route, default_options(), 5);
  const robot::CameraMount mount(0.5, 0.1);
  for (double t : {0.0, 13.2, 40.7, 77.1}) {
    const robot::RobotState s = motion.state_at(at_s(t));
    const Pose cam = mount.camera_to_world(s);
    EXPECT_NEAR(cam.translation().z(), 0.5, 1e-12);
    EXPECT_NEAR((cam.translation().head<2>() - s.position_m).norm(), 0.0, 1e-12);
    EXPECT_NEAR(std::remainder(camera_yaw_rad(cam) - s.heading_rad, 2 * std::numbers::pi), 0.0,
                1e-9);
    // Pitched up: the optical axis points upwards by the pitch.
    EXPECT_NEAR(std::asin(cam.linear().col(2).z()), 0.1, 1e-9);
    // camera = base * camera_in_base.
    const Pose composed = s.base_to_world() * mount.camera_in_base();
    EXPECT_TRUE(composed.isApprox(cam, 1e-12));
  }
}

// Issue 18: a route that turns back at a dead end ("arc length does not increase") could not be
// generated. The robot stands and turns at its yaw-rate limit, then drives back.
TEST(MotionProfile, DeadEndIsATurnOnTheSpotAtTheYawRateLimit) {
  const world::RoutePath route = test::there_and_back_route(10.0);
  robot::RobotMotionOptions options = default_options();
  options.pause.duration_s = 0.0;
  const robot::MotionProfile motion(route, options, 3);
  const double turn_s = std::numbers::pi / 0.6;
  EXPECT_NEAR(motion.end_time().seconds(), 20.0 / 0.5 + turn_s, 1e-5);
  EXPECT_NEAR(motion.moving_time_s(), 20.0 / 0.5 + turn_s, 1e-5);
  // Arrives at the dead end after 20 s, turns for pi / 0.6 s without moving, and comes back.
  for (double t = 20.0 + 0.01; t < 20.0 + turn_s - 0.01; t += 0.25) {
    const robot::RobotState s = motion.state_at(at_s(t));
    EXPECT_NEAR(s.position_m.x(), 10.0, 1e-9) << t;
    EXPECT_EQ(s.speed_mps, 0.0) << t;
    EXPECT_NEAR(s.yaw_rate_radps, 0.6, 1e-3) << t;
    EXPECT_FALSE(s.paused()) << t;
    EXPECT_NEAR(s.arc_length_m, 10.0, 1e-9) << t;
    EXPECT_NEAR(std::remainder(s.heading_rad - 0.6 * (t - 20.0), 2 * std::numbers::pi), 0.0, 2e-3)
        << t;
  }
  const robot::RobotState back = motion.state_at(at_s(20.0 + turn_s + 4.0));
  EXPECT_NEAR(back.position_m.x(), 8.0, 1e-3);
  EXPECT_NEAR(std::abs(back.heading_rad), std::numbers::pi, 1e-9);
  EXPECT_NEAR(back.arc_length_m, 12.0, 1e-3);
  const robot::RobotState end = motion.state_at(motion.end_time());
  EXPECT_NEAR(end.position_m.norm(), 0.0, 1e-9);
  EXPECT_NEAR(end.arc_length_m, 20.0, 1e-9);
}

// Pauses fall before or after the turn, never inside it, and the turn keeps its length.
TEST(MotionProfile, PausesAroundATurnOnTheSpotKeepItsDuration) {
  const world::RoutePath route = test::there_and_back_route(10.0);
  const robot::MotionProfile motion(route, default_options(), 3);
  const double turn_s = std::numbers::pi / 0.6;
  const double paused_s = 10.0 * static_cast<double>(motion.pauses().size());
  EXPECT_NEAR(motion.end_time().seconds(), 20.0 / 0.5 + turn_s + paused_s, 1e-5);
  for (const robot::RobotPause& p : motion.pauses()) {
    const robot::RobotState s = motion.state_at(Timestamp::from_ns((p.start.ns + p.end.ns) / 2));
    EXPECT_TRUE(s.paused());
    EXPECT_EQ(s.yaw_rate_radps, 0.0);
  }
}

TEST(MotionProfile, RejectsARouteWithoutLength) {
  world::RoutePath one_point;
  test::append_point(one_point, {0, 0}, 0);
  EXPECT_THROW(robot::MotionProfile(one_point, default_options(), 1), InvalidInputError);
}

}  // namespace
}  // namespace wifislam::sim
