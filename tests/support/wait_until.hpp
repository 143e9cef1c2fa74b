#pragma once
// Waits for what a test cannot be told about and must poll: a file another process writes, a
// daemon's state, a process going away. It decides nothing: it returns the condition as last
// seen, and the caller asserts it, so a timeout fails the test rather than passing it.

#include <chrono>
#include <thread>

namespace wifislam::test {

/// Polls `done()` every `poll` until it holds or `timeout` passed; returns done().
template <class Condition>
bool wait_until(std::chrono::steady_clock::duration timeout, Condition done,
                std::chrono::steady_clock::duration poll = std::chrono::milliseconds(50)) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!done()) {
    if (std::chrono::steady_clock::now() >= deadline) return done();
    std::this_thread::sleep_for(poll);
  }
  return true;
}

}  // namespace wifislam::test
