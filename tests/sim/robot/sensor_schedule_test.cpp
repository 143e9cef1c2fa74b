#include "sim/robot/sensor_schedule.hpp"

#include <gtest/gtest.h>

#include "tests/sim/robot/test_routes.hpp"

namespace wifislam::sim {
namespace {

robot::RobotMotionOptions motion_options(bool scan_while_moving = false) {
  robot::RobotMotionOptions o;
  o.pause.spacing_min_m = 3.0;
  o.pause.spacing_max_m = 4.0;
  o.pause.duration_s = 10.0;
  o.pause.scan_while_moving = scan_while_moving;
  return o;
}

robot::SensorScheduleOptions schedule_options(bool scan_while_moving = false) {
  robot::SensorScheduleOptions o;
  o.fps = 30.0;
  o.scan_interval_s = 2.0;
  o.scan_duration_ns = 3'500'000'000;  // 35 channels x 0.1 s
  o.scan_while_moving = scan_while_moving;
  return o;
}

TEST(SensorSchedule, FrameTimesAreWholeMicrosecondsAtTheFrameRate) {
  const robot::MotionProfile motion(test::straight_route(20.0), motion_options(), 2);
  const robot::SensorSchedule schedule(motion, schedule_options());
  ASSERT_GT(schedule.frame_count(), 100);
  EXPECT_EQ(schedule.frame_time(0).ns, 0);
  for (std::int64_t k = 1; k < schedule.frame_count(); ++k) {
    const Timestamp t = schedule.frame_time(k);
    EXPECT_EQ(t.ns % 1000, 0);
    const std::int64_t gap_us = (t.ns - schedule.frame_time(k - 1).ns) / 1000;
    EXPECT_TRUE(gap_us == 33333 || gap_us == 33334) << gap_us;
  }
  // Frames cover the whole run and not a frame more.
  EXPECT_LE(schedule.frame_time(schedule.frame_count() - 1), motion.end_time());
  EXPECT_GT(schedule.frame_time(schedule.frame_count()), motion.end_time());
  // Frames keep coming during pauses, as from a real camera.
  const robot::RobotPause& pause = motion.pauses()[1];
  int frames_in_pause = 0;
  for (std::int64_t k = 0; k < schedule.frame_count(); ++k) {
    const Timestamp t = schedule.frame_time(k);
    frames_in_pause += t >= pause.start && t < pause.end;
  }
  EXPECT_EQ(frames_in_pause, 300);
}

TEST(SensorSchedule, ScansHappenOnlyDuringPauses) {
  const robot::MotionProfile motion(test::rounded_rectangle_route(20.0, 12.0, 0.6),
                                    motion_options(), 4);
  const robot::SensorSchedule schedule(motion, schedule_options());
  // 10 s pause, 3.5 s sweeps every 2 s: sweeps starting at 0, 2, 4 and 6 s fit.
  ASSERT_EQ(schedule.scans().size(), 4 * motion.pauses().size());
  for (const robot::ScanWindow& w : schedule.scans()) {
    ASSERT_GE(w.pause_index, 0);
    const robot::RobotPause& p = motion.pauses()[w.pause_index];
    EXPECT_GE(w.start, p.start);
    EXPECT_LE(w.end, p.end);
    EXPECT_EQ(w.end.ns - w.start.ns, 3'500'000'000);
    for (const Timestamp t : {w.start, w.end}) {
      const robot::RobotState s = motion.state_at(t);
      EXPECT_EQ(s.pause_index, w.pause_index);
      EXPECT_EQ(s.speed_mps, 0.0);
    }
  }
}

TEST(SensorSchedule, ScanningWhileMovingCoversTheWholeRun) {
  const robot::MotionProfile motion(test::straight_route(30.0), motion_options(true), 4);
  const robot::SensorSchedule schedule(motion, schedule_options(true));
  const auto& scans = schedule.scans();
  ASSERT_GT(scans.size(), 10u);
  int while_moving = 0;
  for (std::size_t i = 0; i < scans.size(); ++i) {
    EXPECT_EQ(scans[i].start.ns, static_cast<std::int64_t>(i) * 2'000'000'000);
    while_moving += motion.state_at(scans[i].start).speed_mps > 0.0;
  }
  EXPECT_GT(while_moving, 10);
  EXPECT_LE(scans.back().end, motion.end_time());
}

TEST(SensorSchedule, MaxFramesEndsTheRunAtTheLastFrame) {
  const robot::MotionProfile motion(test::straight_route(30.0), motion_options(), 4);
  robot::SensorScheduleOptions options = schedule_options();
  options.max_frames = 450;  // 15 s: the first pause and 5 s of driving
  const robot::SensorSchedule schedule(motion, options);
  EXPECT_EQ(schedule.frame_count(), 450);
  EXPECT_EQ(schedule.end_time(), schedule.frame_time(449));
  EXPECT_EQ(schedule.odometry_count(), robot::tick_count(schedule.end_time(), 50.0));
  EXPECT_EQ(schedule.scans().size(), 4u);  // only the first pause's
  for (const robot::ScanWindow& w : schedule.scans()) EXPECT_LE(w.end, schedule.end_time());
}

TEST(SensorSchedule, TickCountMatchesTickTimes) {
  for (double rate : {30.0, 29.97, 7.0, 50.0, 0.5}) {
    for (std::int64_t end_us : {0LL, 1LL, 33333LL, 33334LL, 1000000LL, 123456789LL}) {
      const Timestamp end = Timestamp::from_ns(end_us * 1000);
      const std::int64_t n = robot::tick_count(end, rate);
      EXPECT_LE(robot::tick_time(n - 1, rate), end);
      EXPECT_GT(robot::tick_time(n, rate), end);
    }
  }
}

TEST(SensorSchedule, AThrottledScannerGrantsAtMostItsRequestsInAnyWindowAndTheRestInOrder) {
  const robot::MotionProfile motion(test::rounded_rectangle_route(20.0, 12.0, 0.6),
                                    motion_options(), 4);
  const robot::SensorSchedule free_running(motion, schedule_options());
  robot::SensorScheduleOptions throttled_options = schedule_options();
  throttled_options.throttle_max_scans = 4;  // Android 9+ foreground: 4 in any 120 s
  throttled_options.throttle_window_s = 120.0;
  const robot::SensorSchedule throttled(motion, throttled_options);
  const auto& all = free_running.scans();
  const auto& kept = throttled.scans();
  ASSERT_GT(all.size(), 20u);
  // Every request is either granted or counted as refused, and the granted ones are requests.
  EXPECT_EQ(kept.size() + static_cast<std::size_t>(throttled.throttled_requests()), all.size());
  EXPECT_GT(throttled.throttled_requests(), 0);
  std::size_t j = 0;
  for (const robot::ScanWindow& w : kept) {
    while (j < all.size() && all[j].start != w.start) ++j;
    ASSERT_LT(j, all.size()) << "a granted scan at " << w.start.seconds() << " s was not asked for";
    EXPECT_EQ(all[j].pause_index, w.pause_index);
  }
  // No window of 120 s holds more than four granted requests ...
  for (std::size_t a = 0; a < kept.size(); ++a) {
    std::size_t in_window = 0;
    for (std::size_t b = a;
         b < kept.size() && kept[b].start.ns - kept[a].start.ns <= 120'000'000'000; ++b)
      ++in_window;
    EXPECT_LE(in_window, 4u) << "from " << kept[a].start.seconds() << " s";
  }
  // ... and a refused request had four granted in the 120 s before it.
  std::size_t k = 0;
  for (const robot::ScanWindow& request : all) {
    while (k < kept.size() && kept[k].start < request.start) ++k;
    if (k < kept.size() && kept[k].start == request.start) continue;
    std::size_t before = 0;
    for (const robot::ScanWindow& g : kept)
      before += g.start < request.start && request.start.ns - g.start.ns <= 120'000'000'000;
    EXPECT_EQ(before, 4u) << "refused at " << request.start.seconds() << " s";
  }
}

}  // namespace
}  // namespace wifislam::sim
