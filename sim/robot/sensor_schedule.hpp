#pragma once
// When each sensor fires during a run: camera frames at `fps`, wheel odometry at its rate, and
// Wi-Fi scans. All times are whole microseconds (frame k at round(k * 1e6 / fps) us), so the
// 6-decimal timestamps of TUM files are exact and a frame's file name is its time.
//
// Scans (paper, "Wi-Fi data processing": the card needs the robot stationary for steady
// readings): during each pause, one scan starts every `scan_interval_s` from the pause's start
// as long as it ends within the pause. With `scan_while_moving` the scanner instead runs
// throughout the run, one scan every `scan_interval_s` from time 0.
//
// A throttled scanner (a phone's operating system: radio_model/receiver_device.hpp) grants at most
// `throttle_max_scans` requests in any `throttle_window_s`: a request is refused when that many
// were granted in the window ending at it (Android's WifiScanRequestProxy counts the requests of
// the last two minutes the same way). A refused request scans nothing: an app then reads the
// previous scan's results again, which a dataset does not repeat; `throttled_requests()` counts
// them.
//
// `max_frames` shortens the run: it then ends at the last frame's time, and scans and odometry
// stop there too.

#include <cstdint>
#include <vector>

#include "core/timestamp.hpp"
#include "sim/robot/motion_profile.hpp"

namespace wifislam::sim::robot {

struct SensorScheduleOptions {
  double fps = 30.0;                  // Kinect v1 rate; lower it to make shorter datasets
  double odometry_rate_hz = 50.0;     // TurtleBot 2 base publishes odometry at 50 Hz
  double scan_interval_s = 2.0;       // from one scan's start to the next's
  std::int64_t scan_duration_ns = 0;  // from the scanner: dwell x channels
  bool scan_while_moving = false;
  int throttle_max_scans = 0;  // 0: every request is granted
  double throttle_window_s = 0.0;
  std::int64_t max_frames = -1;  // < 0: as many as the route takes
};

/// One scheduled Wi-Fi scan: the sweep runs from `start` to `end`; the result is reported at `end`.
struct ScanWindow {
  Timestamp start, end;
  int pause_index = -1;  // the pause it belongs to; -1 for scans while moving
};

class SensorSchedule {
 public:
  /// Throws InvalidInputError for a non-positive fps, odometry rate or scan interval.
  SensorSchedule(const MotionProfile& motion, const SensorScheduleOptions& options);

  std::int64_t frame_count() const { return frame_count_; }
  Timestamp frame_time(std::int64_t k) const;
  std::int64_t odometry_count() const { return odometry_count_; }
  Timestamp odometry_time(std::int64_t j) const;
  const std::vector<ScanWindow>& scans() const { return scans_; }
  /// Scan requests the throttle refused (none without one).
  std::int64_t throttled_requests() const { return throttled_requests_; }
  /// The end of the run (the route's end, or the last frame's time with max_frames).
  Timestamp end_time() const { return end_; }
  const SensorScheduleOptions& options() const { return options_; }

 private:
  SensorScheduleOptions options_;
  Timestamp end_;
  std::int64_t frame_count_ = 0, odometry_count_ = 0, throttled_requests_ = 0;
  std::vector<ScanWindow> scans_;
};

/// Time of tick k of a clock at `rate_hz`, rounded to whole microseconds.
Timestamp tick_time(std::int64_t k, double rate_hz);
/// Number of ticks k >= 0 with tick_time(k) <= end.
std::int64_t tick_count(Timestamp end, double rate_hz);

}  // namespace wifislam::sim::robot
