#pragma once
// Wall-clock time for stage timings and progress (not simulated time: that is Timestamp).

#include <chrono>

namespace wifislam {

using WallClock = std::chrono::steady_clock;

/// Seconds of wall-clock time since `start`.
inline double seconds_since(WallClock::time_point start) {
  return std::chrono::duration<double>(WallClock::now() - start).count();
}

}  // namespace wifislam
