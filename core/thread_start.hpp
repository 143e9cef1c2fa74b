#pragma once
// Starting worker threads when the machine may not give us as many as asked: a process or
// memory limit makes std::thread's constructor throw std::system_error, and a thread that was
// started and then destroyed unjoined ends the program (std::terminate). These helpers start as
// many as the machine allows and let the caller work with those.

#include <pthread.h>

#include <algorithm>
#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

namespace wifislam {

/// Largest default stack for threads the process starts from now on.
inline constexpr std::size_t kMaxDefaultThreadStackBytes = std::size_t{16} << 20;

/// glibc gives every new thread a stack of RLIMIT_STACK (`ulimit -s`) unless told otherwise, so a
/// large limit (256 MB) times a few worker threads exhausts an address-space limit (`ulimit -v`),
/// and later allocations fail with bad_alloc at random. Our threads (PNG encoding, radio maps,
/// study cases, llvmpipe's) need far less: cap the default at 16 MB, twice Linux's usual 8 MB.
/// Call once at the start of main(). No-op where the default is already smaller.
inline void cap_default_thread_stack() {
  pthread_attr_t attr;
  if (pthread_getattr_default_np(&attr) != 0) return;
  std::size_t size = 0;
  if (pthread_attr_getstacksize(&attr, &size) == 0 && size > kMaxDefaultThreadStackBytes &&
      pthread_attr_setstacksize(&attr, kMaxDefaultThreadStackBytes) == 0) {
    pthread_setattr_default_np(&attr);
  }
  pthread_attr_destroy(&attr);
}

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

/// Runs `worker` on the calling thread and on up to `threads - 1` helpers (as many as the system
/// starts), joins them all, then rethrows the first exception any of them threw. An exception
/// must not leave a helper thread (std::terminate) or leave helpers running unjoined; the worker
/// shares its work through its own counter, so any number of threads gives the same result.
template <class F>
void run_on_threads(int threads, const F& worker) {
  std::mutex error_mutex;
  std::exception_ptr first_error;
  const auto guarded = [&] {
    try {
      worker();
    } catch (...) {
      std::lock_guard lock(error_mutex);
      if (!first_error) first_error = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  start_threads(pool, threads - 1, guarded);
  guarded();
  for (std::thread& t : pool) t.join();
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace wifislam
