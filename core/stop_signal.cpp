#include "core/stop_signal.hpp"

#include <csignal>
#include <cstring>
#include <iterator>

#include <signal.h>

#include <fmt/format.h>

namespace wifislam {

namespace {

constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP};
volatile std::sig_atomic_t g_stop_signal = 0;
struct sigaction g_previous[std::size(kStopSignals)];

void on_stop_signal(int signal) {
  if (g_stop_signal != 0) {
    // Asked twice: the default action now (async-signal-safe: signal and raise).
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  g_stop_signal = signal;
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
  stop.sa_flags = SA_RESTART;  // reads and writes go on; the work stops at its next frame
  for (std::size_t i = 0; i < std::size(kStopSignals); ++i)
    ::sigaction(kStopSignals[i], &stop, &g_previous[i]);
}

StopOnSignal::~StopOnSignal() {
  for (std::size_t i = 0; i < std::size(kStopSignals); ++i)
    ::sigaction(kStopSignals[i], &g_previous[i], nullptr);
}

void throw_if_stop_requested() {
  if (const int signal = g_stop_signal) throw StoppedBySignal(signal);
}

}  // namespace wifislam
