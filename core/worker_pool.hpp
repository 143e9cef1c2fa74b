#pragma once
// The project's worker threads, in two shapes, both on core/thread_start.hpp (as many threads as
// the system will start, never an unjoined one, the first exception rethrown):
//
//  - parallel_for(threads, count, body): body(0 .. count-1) on the calling thread and helpers,
//    indices taken from one counter, for work whose items are independent (radio-map rows, study
//    cases, the SLAM runs of a comparison). Results must not depend on which thread ran an item;
//    callers write each item's result to its own slot.
//  - WorkerPool: a fixed set of threads running submitted jobs in submission order, results
//    collected through futures; for a producer that streams work and consumes results in order
//    (the dataset writer: the calling thread renders, workers encode PNGs, lists are written in
//    frame order).

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

#include "core/thread_start.hpp"

namespace wifislam {

/// Runs body(i) for each i in [0, count) on the calling thread and up to `threads - 1` helpers
/// (`threads` as clamp_thread_count gives it; never more threads than items). After an item
/// throws, no thread takes a new one; the first exception is rethrown once every thread is done.
template <class Body>
void parallel_for(int threads, std::size_t count, const Body& body) {
  if (count == 0) return;
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  const int n = static_cast<int>(
      std::min<std::size_t>(static_cast<std::size_t>(std::max(1, threads)), count));
  run_on_threads(n, [&] {
    for (std::size_t i = next++; i < count && !failed; i = next++) {
      try {
        body(i);
      } catch (...) {
        failed = true;
        throw;
      }
    }
  });
}

/// Worker threads running jobs first in, first out. Starts as many of the requested threads as
/// the system allows (`size()`, possibly 0: then submit() runs the job inline). The destructor
/// finishes the queued jobs and joins.
class WorkerPool {
 public:
  explicit WorkerPool(int threads) {
    start_threads(workers_, threads, [this] { run(); });
  }
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;
  ~WorkerPool() {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& w : workers_) w.join();
  }

  int size() const { return static_cast<int>(workers_.size()); }

  /// Queues `job`; its result (or exception) arrives through the future.
  template <class F>
  std::future<std::invoke_result_t<F>> submit(F job) {
    std::packaged_task<std::invoke_result_t<F>()> task(std::move(job));
    auto future = task.get_future();
    if (workers_.empty()) {
      task();
      return future;
    }
    {
      std::lock_guard lock(mutex_);
      // packaged_task is move-only; std::function needs a copyable callable.
      jobs_.push_back([t = std::make_shared<decltype(task)>(std::move(task))] { (*t)(); });
    }
    wake_.notify_one();
    return future;
  }

 private:
  void run() {
    while (true) {
      std::function<void()> job;
      {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [&] { return stopping_ || !jobs_.empty(); });
        if (jobs_.empty()) return;
        job = std::move(jobs_.front());
        jobs_.pop_front();
      }
      job();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  bool stopping_ = false;
  std::vector<std::thread> workers_;
};

}  // namespace wifislam
