#include "core/stop_signal.hpp"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <exception>
#include <iterator>

#include <signal.h>

#include <fmt/format.h>

namespace wifislam {

namespace {

constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP};
// Set by the handler, which may run on any thread, and read by the work: a lock-free atomic is
// both async-signal-safe and free of data races.
std::atomic<int> g_stop_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);
struct sigaction g_previous[std::size(kStopSignals)];
bool g_installed[std::size(kStopSignals)] = {};

void on_stop_signal(int signal) {
  if (g_stop_signal.load() != 0) {
    // Asked twice: the default action now (async-signal-safe: signal and raise).
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  g_stop_signal.store(signal);
}

}  // namespace

StoppedBySignal::StoppedBySignal(int signal)
    : Error(fmt::format("stopped by {}; the unfinished output was removed",
                        signal == SIGINT    ? "Ctrl-C (SIGINT)"
                        : signal == SIGTERM ? "SIGTERM"
                                            : "SIGHUP")),
      signal_(signal) {}

StopOnSignal::StopOnSignal() {
  struct sigaction stop {};
  stop.sa_handler = on_stop_signal;
  sigemptyset(&stop.sa_mask);
  stop.sa_flags = SA_RESTART;  // reads and writes go on; the work stops at its next check
  for (std::size_t i = 0; i < std::size(kStopSignals); ++i) {
    // A signal the caller ignores stays ignored: under nohup (SIGHUP) or as a script's
    // background job (SIGINT) the run goes on, as it did before the guard.
    ::sigaction(kStopSignals[i], nullptr, &g_previous[i]);
    g_installed[i] = g_previous[i].sa_handler != SIG_IGN;
    if (g_installed[i]) ::sigaction(kStopSignals[i], &stop, nullptr);
  }
}

StopOnSignal::~StopOnSignal() {
  for (std::size_t i = 0; i < std::size(kStopSignals); ++i) {
    if (g_installed[i]) ::sigaction(kStopSignals[i], &g_previous[i], nullptr);
    g_installed[i] = false;
  }
  // A signal that came after the last check (the output was already committed) is not lost: the
  // process ends by it, as the caller (a shell loop) expects. While StoppedBySignal unwinds, the
  // command's caller reports it and ends the process so.
  // What the command printed goes out first: stdout to a pipe or file is block-buffered, and the
  // signal's default action ends the process without flushing it.
  const int signal = g_stop_signal.load();
  if (signal != 0 && std::uncaught_exceptions() == 0) {
    std::fflush(nullptr);
    std::raise(signal);
  }
}

int stop_requested_signal() { return g_stop_signal.load(); }

void throw_if_stop_requested() {
  if (const int signal = g_stop_signal.load()) throw StoppedBySignal(signal);
}

}  // namespace wifislam
