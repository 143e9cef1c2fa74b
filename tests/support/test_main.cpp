// Every suite's main: GoogleTest's, plus a report when a test process dies of a signal.
//
// ctest shows a crashed test as "SegFault" with the test's output, and GoogleTest prints nothing
// of a crash, so a rare crash on a CI machine leaves nothing to go on. Here a fatal signal prints
// the test that was running and a backtrace to stderr, then the process dies of the same signal
// (ctest still sees the crash). Frames of the test executable print as `binary(+0xoffset)`:
// `addr2line -f -C -e <binary> <offset>` on a build of the same commit names the line.

#include <execinfo.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <cstddef>
#include <cstring>

namespace {

// Written from the handler, so everything it prints is ready beforehand in fixed buffers.
char running_test[512] = "(no test running)";
char alternate_stack[64 * 1024];  // the handler's stack: a stack overflow leaves none of its own

void write_text(const char* text) {
  std::size_t left = std::strlen(text);
  while (left > 0) {
    const ssize_t written = ::write(STDERR_FILENO, text, left);
    if (written <= 0) return;
    text += written;
    left -= static_cast<std::size_t>(written);
  }
}

extern "C" void report_fatal_signal(int signal_number) {
  // Only async-signal-safe calls: write, backtrace (primed below), backtrace_symbols_fd, raise.
  write_text("\n*** fatal signal ");
  write_text(::strsignal(signal_number) != nullptr ? ::strsignal(signal_number) : "?");
  write_text(" in test ");
  write_text(running_test);
  write_text("; backtrace (innermost first):\n");
  void* frames[64];
  const int count = ::backtrace(frames, 64);
  ::backtrace_symbols_fd(frames, count, STDERR_FILENO);
  // SA_RESETHAND restored the default action: dying of the same signal is what ctest reports.
  ::raise(signal_number);
}

class RunningTestName : public ::testing::EmptyTestEventListener {
  void OnTestStart(const ::testing::TestInfo& info) override {
    const std::string name = std::string(info.test_suite_name()) + "." + info.name();
    std::strncpy(running_test, name.c_str(), sizeof running_test - 1);
  }
  void OnTestEnd(const ::testing::TestInfo&) override {
    std::strncpy(running_test, "(between tests)", sizeof running_test - 1);
  }
};

void install_fatal_signal_report() {
  // backtrace() loads libgcc's unwinder on its first call, which allocates: not in a handler.
  void* warm_up[1];
  ::backtrace(warm_up, 1);
  stack_t stack{};
  stack.ss_sp = alternate_stack;
  stack.ss_size = sizeof alternate_stack;
  ::sigaltstack(&stack, nullptr);
  struct sigaction action {};
  action.sa_handler = report_fatal_signal;
  action.sa_flags = SA_ONSTACK | SA_RESETHAND;
  sigemptyset(&action.sa_mask);
  for (const int signal_number : {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT}) {
    ::sigaction(signal_number, &action, nullptr);
  }
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
#if !defined(__SANITIZE_ADDRESS__)
  // Under AddressSanitizer its own SEGV report, with the faulting access, is the better one.
  install_fatal_signal_report();
#endif
  ::testing::UnitTest::GetInstance()->listeners().Append(new RunningTestName);
  return RUN_ALL_TESTS();
}
