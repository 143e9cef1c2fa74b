// Workers on threads the machine may refuse: an exception thrown on a helper thread reaches the
// caller after every thread has been joined, instead of ending the program (std::terminate).

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>

#include "core/thread_start.hpp"

namespace wifislam {
namespace {

TEST(RunOnThreads, AnExceptionOnAHelperThreadReachesTheCallerAfterAllAreJoined) {
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> finished{0}, helpers{0};
  const auto worker = [&] {
    if (std::this_thread::get_id() != caller) {
      if (helpers++ == 0) throw std::runtime_error("bad cell");
    }
    ++finished;
  };
  try {
    run_on_threads(4, worker);
    // A machine that starts no helper runs the worker on the caller only.
    EXPECT_EQ(helpers.load(), 0);
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "bad cell");
    EXPECT_GE(helpers.load(), 1);
    // The caller and every helper but the one that threw ran to the end.
    EXPECT_EQ(finished.load(), helpers.load());
  }
}

TEST(RunOnThreads, EveryThreadRunsTheWorkerOnce) {
  std::atomic<int> runs{0};
  run_on_threads(3, [&] { ++runs; });
  EXPECT_GE(runs.load(), 1);
  EXPECT_LE(runs.load(), 3);
  std::atomic<int> alone{0};
  run_on_threads(1, [&] {
    EXPECT_EQ(alone++, 0);  // the caller alone
  });
  EXPECT_EQ(alone.load(), 1);
}

}  // namespace
}  // namespace wifislam
