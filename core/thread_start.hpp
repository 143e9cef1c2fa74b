#pragma once
// Starting worker threads when the machine may not give us as many as asked: a process or
// memory limit makes std::thread's constructor throw std::system_error, and a thread that was
// started and then destroyed unjoined ends the program (std::terminate). These helpers start as
// many as the machine allows and let the caller work with those.

#include <algorithm>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

namespace wifislam {

/// Upper bound for a user's thread count: 4 per core (at least 4). More threads than that only
/// cost memory (each has its own stack) for CPU-bound work such as PNG encoding.
inline int max_useful_threads() {
  return 4 * std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

/// `requested` (0 = one per core) clamped to [1, max_useful_threads()].
inline int clamp_thread_count(int requested) {
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  return std::clamp(requested > 0 ? requested : cores, 1, max_useful_threads());
}

/// Starts up to `count` threads running `body` (copied into each) and appends them to `pool`.
/// Returns how many were started: fewer than `count` when the system refuses more (the
/// std::system_error is swallowed; the caller works with what it has, or none).
template <class F>
int start_threads(std::vector<std::thread>& pool, int count, const F& body) {
  pool.reserve(pool.size() + static_cast<std::size_t>(std::max(0, count)));
  int started = 0;
  for (; started < count; ++started) {
    try {
      pool.emplace_back(body);
    } catch (const std::system_error&) {
      break;
    }
  }
  return started;
}

}  // namespace wifislam
