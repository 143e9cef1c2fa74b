#include "sim/robot/sensor_schedule.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace wifislam::sim::robot {

Timestamp tick_time(std::int64_t k, double rate_hz) {
  return Timestamp::from_ns(std::llround(static_cast<double>(k) * 1e6 / rate_hz) * 1000);
}

std::int64_t tick_count(Timestamp end, double rate_hz) {
  if (end.ns < 0) return 0;
  std::int64_t k = static_cast<std::int64_t>(std::floor(end.seconds() * rate_hz));
  // The rounding of tick_time may move the boundary by one tick either way.
  while (k >= 0 && tick_time(k, rate_hz) > end) --k;
  while (tick_time(k + 1, rate_hz) <= end) ++k;
  return k + 1;
}

SensorSchedule::SensorSchedule(const MotionProfile& motion, const SensorScheduleOptions& options)
    : options_(options) {
  if (!(options_.fps > 0.0)) throw InvalidInputError("sensor schedule: fps must be positive");
  if (!(options_.odometry_rate_hz > 0.0))
    throw InvalidInputError("sensor schedule: odometry rate must be positive");
  if (!(options_.scan_interval_s > 0.0))
    throw InvalidInputError("sensor schedule: scan_interval_s must be positive");
  if (options_.throttle_max_scans > 0 && !(options_.throttle_window_s > 0.0))
    throw InvalidInputError("sensor schedule: a scan throttle needs a positive window");
  if (options_.scan_duration_ns < 0)
    throw InvalidInputError("sensor schedule: scan duration must not be negative");

  end_ = motion.end_time();
  frame_count_ = tick_count(end_, options_.fps);
  if (options_.max_frames >= 0 && options_.max_frames < frame_count_) {
    frame_count_ = options_.max_frames;
    end_ = frame_count_ > 0 ? frame_time(frame_count_ - 1) : Timestamp{0};
  }
  odometry_count_ = tick_count(end_, options_.odometry_rate_hz);

  const std::int64_t interval_ns = std::llround(options_.scan_interval_s * 1e6) * 1000;
  const std::int64_t duration_ns = options_.scan_duration_ns;
  const std::int64_t throttle_window_ns = std::llround(options_.throttle_window_s * 1e9);
  // Granted requests are in time order, so the ones inside a window are the last few.
  auto granted = [&](std::int64_t start) {
    if (options_.throttle_max_scans <= 0) return true;
    std::int64_t in_window = 0;
    for (auto it = scans_.rbegin(); it != scans_.rend(); ++it) {
      if (start - it->start.ns > throttle_window_ns) break;
      ++in_window;
    }
    if (in_window < options_.throttle_max_scans) return true;
    ++throttled_requests_;
    return false;
  };
  auto add_scans = [&](std::int64_t from_ns, std::int64_t to_ns, int pause_index) {
    to_ns = std::min(to_ns, end_.ns);
    for (std::int64_t start = from_ns; start + duration_ns <= to_ns; start += interval_ns) {
      if (!granted(start)) continue;
      scans_.push_back(
          {Timestamp::from_ns(start), Timestamp::from_ns(start + duration_ns), pause_index});
    }
  };
  if (options_.scan_while_moving) {
    add_scans(0, end_.ns, -1);
    // Mark the scans that happen to lie inside a pause (useful for grouping signatures).
    const auto& pauses = motion.pauses();
    for (ScanWindow& w : scans_) {
      for (std::size_t p = 0; p < pauses.size(); ++p) {
        if (w.start >= pauses[p].start && w.end <= pauses[p].end)
          w.pause_index = static_cast<int>(p);
      }
    }
  } else {
    const auto& pauses = motion.pauses();
    for (std::size_t p = 0; p < pauses.size(); ++p) {
      add_scans(pauses[p].start.ns, pauses[p].end.ns, static_cast<int>(p));
    }
  }
}

Timestamp SensorSchedule::frame_time(std::int64_t k) const { return tick_time(k, options_.fps); }

Timestamp SensorSchedule::odometry_time(std::int64_t j) const {
  return tick_time(j, options_.odometry_rate_hz);
}

}  // namespace wifislam::sim::robot
