// Every suite's main: GoogleTest's, plus a report when a test process dies of a signal.
//
// ctest shows a crashed test as "SegFault" with the test's output, and GoogleTest prints nothing
// of a crash, so a rare crash on a CI machine leaves nothing to go on. Here a fatal signal prints
// the test that was running and a backtrace to stderr, then the process dies of the same signal
// (ctest still sees the crash). The backtrace is backtrace_symbols_fd's: shared libraries' frames
// by their exported names, the executable's as `binary(+0xoffset)` because its own symbols are
// not exported. So addr2line, run on the executable while it still exists, names those frames
// after it: a CI machine's build is gone when its log is read, and a build elsewhere (another
// checkout path, other __FILE__ strings) may place the code at other offsets.

#include <execinfo.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstring>

// The linker's symbols for the first byte of the executable's image and the end of its code.
extern "C" char __executable_start;
extern "C" char etext;

namespace {

// Used from the handler, so everything it needs is ready beforehand in fixed buffers.
char running_test[512] = "(no test running)";
char executable_path[4096] = "";
char alternate_stack[64 * 1024];  // the handler's stack: a stack overflow leaves none of its own
constexpr int kMaxFrames = 64;
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif

void write_text(const char* text) {
  std::size_t left = std::strlen(text);
  while (left > 0) {
    const ssize_t written = ::write(STDERR_FILENO, text, left);
    if (written <= 0) return;
    text += written;
    left -= static_cast<std::size_t>(written);
  }
}

const char* signal_name(int signal_number) {
  switch (signal_number) {
    case SIGSEGV:
      return "SIGSEGV (segmentation fault)";
    case SIGBUS:
      return "SIGBUS (bus error)";
    case SIGILL:
      return "SIGILL (illegal instruction)";
    case SIGFPE:
      return "SIGFPE (arithmetic exception)";
    case SIGABRT:
      return "SIGABRT (abort)";
    default:
      return "(another signal)";
  }
}

/// "0x<hex>" of `value` into `out` (at least 19 bytes): snprintf is not async-signal-safe.
void format_hex(std::uintptr_t value, char* out) {
  char digits[16];
  int n = 0;
  do {
    digits[n++] = "0123456789abcdef"[value & 0xf];
    value >>= 4;
  } while (value != 0);
  *out++ = '0';
  *out++ = 'x';
  while (n > 0) *out++ = digits[--n];
  *out = '\0';
}

/// Runs addr2line on the frames in the executable's code, printing their function names.
void name_own_frames(void* const* frames, int count) {
  if (executable_path[0] == '\0') return;
  static char offsets[kMaxFrames][20];
  // Without debug information addr2line's "at file:?" names whichever source file the linker
  // listed last before the function, often not its own: only the function name is kept.
  const char* argv[kMaxFrames + 8] = {
      "sh", "-c", "/usr/bin/addr2line -f -C -p -e \"$0\" \"$@\" | /usr/bin/sed 's/ at [^ ]*:?$//'",
      executable_path};
  constexpr int kFixedArguments = 4;
  int argc = kFixedArguments;
  const auto begin = reinterpret_cast<std::uintptr_t>(&__executable_start);
  const auto end = reinterpret_cast<std::uintptr_t>(&etext);
  for (int i = 0; i < count; ++i) {
    const auto address = reinterpret_cast<std::uintptr_t>(frames[i]);
    if (address < begin || address >= end) continue;
    // A return address is the instruction after the call: one byte back is the call's line.
    format_hex(address - begin - (i > 0 ? 1 : 0), offsets[i]);
    argv[argc++] = offsets[i];
  }
  if (argc == kFixedArguments) return;
  argv[argc] = nullptr;
  write_text("the executable's frames, named by addr2line (innermost first):\n");
  // The raw system call: glibc's fork() runs the atfork handlers of the libraries loaded, which may
  // take locks the crashed thread holds. The child only redirects a descriptor and execs.
  const long child = ::syscall(SYS_fork);
  if (child == 0) {
    ::dup2(STDERR_FILENO, STDOUT_FILENO);
    ::execv("/bin/sh", const_cast<char* const*>(argv));
    ::_exit(127);
  }
  if (child > 0) {
    int status = 0;
    ::waitpid(static_cast<pid_t>(child), &status, 0);
  }
}

extern "C" void report_fatal_signal(int signal_number) {
  // Only async-signal-safe calls, but backtrace (primed at installation, so it does not load
  // libgcc here) and backtrace_symbols_fd, which glibc writes without allocating.
  write_text("\n*** fatal signal ");
  write_text(signal_name(signal_number));
  write_text(" in test ");
  write_text(running_test);
  write_text("; backtrace (innermost first):\n");
  void* frames[kMaxFrames];
  const int count = ::backtrace(frames, kMaxFrames);
  ::backtrace_symbols_fd(frames, count, STDERR_FILENO);
  name_own_frames(frames, count);
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
  const ssize_t length = ::readlink("/proc/self/exe", executable_path, sizeof executable_path - 1);
  executable_path[length > 0 ? length : 0] = '\0';
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
  // Under AddressSanitizer its own SEGV report, with the faulting access, is the better one.
  if (!kAddressSanitizer) install_fatal_signal_report();
  ::testing::UnitTest::GetInstance()->listeners().Append(new RunningTestName);
  return RUN_ALL_TESTS();
}
