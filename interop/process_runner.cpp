#include "interop/process_runner.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include <fmt/format.h>

#include "core/stop_signal.hpp"
#include "core/wall_clock.hpp"

extern char** environ;

namespace wifislam::interop {

namespace {

double cpu_seconds(const rusage& usage) {
  const auto seconds = [](const timeval& t) { return t.tv_sec + 1e-6 * t.tv_usec; };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

/// What the supervisor tells the caller through its pipe.
struct Report {
  int kind = 0;  // 1 exited, 2 signalled, 3 timed out, 4 not started, 5 stopped (we were asked)
  int code = 0;  // exit code, signal, errno (not started) or the signal that stopped us
};
constexpr int kExited = 1, kSignalled = 2, kTimedOut = 3, kNotStarted = 4, kStopped = 5;

// ----- The supervisor: a forked child of this (threaded) process, so from fork to _exit it
// ----- calls only async-signal-safe functions: no allocation, no locks, no C++ streams.

volatile sig_atomic_t g_stop_signal = 0;
void on_stop_signal(int signal) { g_stop_signal = signal; }

double now_s() {
  timespec t{};
  ::clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void pause_ms(long ms) {
  timespec t{ms / 1000, (ms % 1000) * 1000000L};
  ::nanosleep(&t, nullptr);  // a signal may cut it short: the loops look again
}

/// The parent pid in /proc/<pid>/stat ("pid (comm) state ppid ..."; comm may hold anything, so
/// the fields are read after its last ')'); -1 when unreadable.
long parent_of(const char* pid_text) {
  char path[64] = "/proc/";
  std::size_t n = 6;
  for (const char* c = pid_text; *c && n < sizeof path - 6; ++c) path[n++] = *c;
  const char* tail = "/stat";
  for (const char* c = tail; *c; ++c) path[n++] = *c;
  path[n] = '\0';
  const int fd = ::open(path, O_RDONLY | O_CLOEXEC);
  if (fd < 0) return -1;
  char buffer[1024];
  const ssize_t got = ::read(fd, buffer, sizeof buffer - 1);
  ::close(fd);
  if (got <= 0) return -1;
  buffer[got] = '\0';
  const char* close = nullptr;
  for (const char* c = buffer; *c; ++c)
    if (*c == ')') close = c;
  if (!close || !close[1] || !close[2] || !close[3]) return -1;
  const char* ppid = close + 4;  // ") S " then the ppid
  long value = 0;
  for (; *ppid >= '0' && *ppid <= '9'; ++ppid) value = value * 10 + (*ppid - '0');
  return value;
}

/// Sends `signal` to every process whose parent is this one (the orphans a subreaper adopts);
/// returns how many.
int signal_children(int signal) {
  struct Dirent64 {
    unsigned long long ino;
    long long off;
    unsigned short reclen;
    unsigned char type;
    char name[1];
  };
  const int dir = ::open("/proc", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir < 0) return 0;
  const long self = static_cast<long>(::getpid());
  int signalled = 0;
  alignas(8) char buffer[8192];
  while (true) {
    const long got = ::syscall(SYS_getdents64, dir, buffer, sizeof buffer);
    if (got <= 0) break;
    for (long offset = 0; offset < got;) {
      const auto* entry = reinterpret_cast<const Dirent64*>(buffer + offset);
      offset += entry->reclen;
      long pid = 0;
      bool numeric = entry->name[0] != '\0';
      for (const char* c = entry->name; *c; ++c) {
        if (*c < '0' || *c > '9') numeric = false;
        pid = pid * 10 + (*c - '0');
      }
      if (!numeric || pid == self) continue;
      if (parent_of(entry->name) == self && ::kill(static_cast<pid_t>(pid), signal) == 0) {
        ++signalled;
      }
    }
  }
  ::close(dir);
  return signalled;
}

/// Ends everything the system started: its group, then every orphan this subreaper adopted
/// (a setsid'd child leaves the group, not us), until this process has no child left.
void end_descendants(pid_t group) {
  ::kill(-group, SIGKILL);
  for (int round = 0; round < 2000; ++round) {  // 20 s at most; a process in D state may lag
    signal_children(SIGKILL);
    int status = 0;
    pid_t done;
    while ((done = ::waitpid(-1, &status, WNOHANG)) > 0) {
    }
    if (done < 0 && errno == ECHILD) return;
    pause_ms(10);
  }
}

[[noreturn]] void supervise(const ProcessRequest& request, const char* program, char* const* argv,
                            int in_fd, int out_fd, int err_fd, int report_fd, pid_t caller) {
  // If the caller dies (even by SIGKILL) the kernel sends us SIGTERM: we end the system then.
  struct sigaction stop {};
  stop.sa_handler = on_stop_signal;
  ::sigemptyset(&stop.sa_mask);
  for (int s : {SIGTERM, SIGINT, SIGHUP}) ::sigaction(s, &stop, nullptr);
  sigset_t none;
  ::sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  ::prctl(PR_SET_CHILD_SUBREAPER, 1);
  Report report;
  if (::getppid() != caller) {  // the caller died before the line above
    report = {kStopped, SIGTERM};
    ::write(report_fd, &report, sizeof report);
    ::_exit(0);
  }
  int exec_pipe[2];
  if (::pipe2(exec_pipe, O_CLOEXEC) != 0) {
    report = {kNotStarted, errno};
    ::write(report_fd, &report, sizeof report);
    ::_exit(0);
  }
  const pid_t system = ::fork();
  if (system == 0) {
    // The system: a process group of its own (a timeout or a stop ends the group); killed if we
    // die; default signal handling; its files; its folder.
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    struct sigaction standard {};
    standard.sa_handler = SIG_DFL;
    for (int s : {SIGTERM, SIGINT, SIGHUP, SIGPIPE, SIGQUIT}) ::sigaction(s, &standard, nullptr);
    ::close(exec_pipe[0]);
    int error = 0;
    if (::dup2(in_fd, 0) < 0 || ::dup2(out_fd, 1) < 0 || ::dup2(err_fd, 2) < 0) error = errno;
    if (!error && ::chdir(request.working_dir.c_str()) != 0) error = errno;
    if (!error) {
      ::execve(program, argv, environ);
      error = errno;
    }
    ::write(exec_pipe[1], &error, sizeof error);
    ::_exit(127);
  }
  ::close(exec_pipe[1]);
  if (system < 0) {
    report = {kNotStarted, errno};
    ::write(report_fd, &report, sizeof report);
    ::_exit(0);
  }
  ::setpgid(system, system);  // also here: no race with our kill(-system) below
  int exec_error = 0;
  if (::read(exec_pipe[0], &exec_error, sizeof exec_error) == sizeof exec_error) {
    ::close(exec_pipe[0]);
    end_descendants(system);
    report = {kNotStarted, exec_error};
    ::write(report_fd, &report, sizeof report);
    ::_exit(0);
  }
  ::close(exec_pipe[0]);

  const double deadline = now_s() + request.timeout_s;
  int status = 0;
  bool ended = false;
  while (!ended) {
    const pid_t done = ::waitpid(system, &status, WNOHANG);
    if (done == system || (done < 0 && errno != EINTR)) {
      ended = true;
      break;
    }
    if (g_stop_signal != 0 || now_s() >= deadline) {
      // Asked to stop, or out of time: SIGTERM to the group, then SIGKILL to everything.
      ::kill(-system, SIGTERM);
      const double grace = now_s() + 2.0;
      while (now_s() < grace && ::waitpid(system, &status, WNOHANG) == 0) pause_ms(10);
      end_descendants(system);
      report = g_stop_signal != 0 ? Report{kStopped, static_cast<int>(g_stop_signal)}
                                  : Report{kTimedOut, 0};
      ::write(report_fd, &report, sizeof report);
      ::_exit(0);
    }
    pause_ms(10);
  }
  end_descendants(system);  // what it started and left running (in its group or not)
  if (WIFEXITED(status)) {
    report = {kExited, WEXITSTATUS(status)};
  } else if (WIFSIGNALED(status)) {
    report = {kSignalled, WTERMSIG(status)};
  } else {
    report = {kSignalled, 0};
  }
  ::write(report_fd, &report, sizeof report);
  ::_exit(0);
}

/// argv[0] as execvp would find it (searched in PATH when it holds no '/'); "" when nowhere.
std::string resolve_program(const std::string& name) {
  if (name.find('/') != std::string::npos) return name;
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path && *path ? path : "/usr/local/bin:/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/" + name;
    struct stat st {};
    if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
        ::access(candidate.c_str(), X_OK) == 0) {
      return candidate;
    }
  }
  return "";
}

int open_output(const std::filesystem::path& file) {
  return ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
}

}  // namespace

std::string ProcessResult::describe(double timeout_s) const {
  switch (status) {
    case Status::kExited:
      return fmt::format("exited {}", exit_code);
    case Status::kSignalled:
      return fmt::format("killed by signal {} ({})", signal, ::strsignal(signal));
    case Status::kTimedOut:
      return fmt::format("timed out after {:g} s", timeout_s);
    case Status::kNotStarted:
      return "not started: " + error;
    case Status::kLost:
      return "exit status lost: " + error;
  }
  return "";
}

ProcessResult run_process(const ProcessRequest& request) {
  ProcessResult result;
  if (request.argv.empty()) {
    result.error = "no command";
    return result;
  }
  // Everything that allocates happens here, before fork.
  const std::string program = resolve_program(request.argv.front());
  if (program.empty()) {
    result.error = fmt::format("{}: {}", request.argv.front(), std::strerror(ENOENT));
    return result;
  }
  std::vector<char*> argv;
  for (const std::string& a : request.argv) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const int in_fd = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  const int out_fd = open_output(request.stdout_file);
  const int err_fd = open_output(request.stderr_file);
  int report_pipe[2] = {-1, -1};
  const auto close_all = [&] {
    for (int fd : {in_fd, out_fd, err_fd, report_pipe[0], report_pipe[1]})
      if (fd >= 0) ::close(fd);
  };
  if (in_fd < 0 || out_fd < 0 || err_fd < 0 || ::pipe2(report_pipe, O_CLOEXEC) != 0) {
    result.error = fmt::format("cannot set up its files: {}", std::strerror(errno));
    close_all();
    return result;
  }

  const auto start = WallClock::now();
  const pid_t caller = ::getpid();
  // The stop signals are held back across the fork: until the supervisor has its own handlers
  // (which unblock them), one landing in it would run the handler it inherited from this process
  // and be lost to it, or end it without a report.
  sigset_t stop_signals, previous_mask;
  ::sigemptyset(&stop_signals);
  for (int s : {SIGTERM, SIGINT, SIGHUP}) ::sigaddset(&stop_signals, s);
  ::pthread_sigmask(SIG_BLOCK, &stop_signals, &previous_mask);
  const pid_t supervisor = ::fork();
  if (supervisor == 0) {
    ::close(report_pipe[0]);
    supervise(request, program.c_str(), argv.data(), in_fd, out_fd, err_fd, report_pipe[1], caller);
  }
  ::pthread_sigmask(SIG_SETMASK, &previous_mask, nullptr);
  ::close(report_pipe[1]);
  report_pipe[1] = -1;
  if (supervisor < 0) {
    result.error = fmt::format("cannot start a process: {}", std::strerror(errno));
    close_all();
    return result;
  }
  int status = 0;
  rusage usage{};
  // Polled rather than blocking: under a command's StopOnSignal guard (core/stop_signal.hpp) a
  // SIGTERM no longer ends wifislam at once, which is what told the supervisor to stop the
  // program; the stop is passed on to it here instead, and it reports the run as stopped.
  bool stop_passed_on = false;
  for (;;) {
    const pid_t done = ::wait4(supervisor, &status, WNOHANG, &usage);
    if (done == supervisor) break;
    if (done < 0 && errno != EINTR) {
      result.status = ProcessResult::Status::kLost;
      result.error = std::string("wait4: ") + std::strerror(errno);
      close_all();
      return result;
    }
    if (!stop_passed_on && stop_requested_signal() != 0) {
      ::kill(supervisor, SIGTERM);
      stop_passed_on = true;
    }
    pause_ms(10);
  }
  Report report;
  const bool reported = ::read(report_pipe[0], &report, sizeof report) == sizeof report;
  close_all();
  result.wall_s = seconds_since(start);
  // The supervisor's and every descendant's, each waited for by it.
  result.cpu_s = cpu_seconds(usage);
  if (!reported) {
    result.status = ProcessResult::Status::kLost;
    result.error = "its supervisor ended without a report";
    return result;
  }
  switch (report.kind) {
    case kExited:
      result.status = ProcessResult::Status::kExited;
      result.exit_code = report.code;
      break;
    case kSignalled:
      result.status = ProcessResult::Status::kSignalled;
      result.signal = report.code;
      break;
    case kTimedOut:
      result.status = ProcessResult::Status::kTimedOut;
      break;
    case kStopped:
      result.status = ProcessResult::Status::kSignalled;
      result.signal = report.code;
      result.error = "stopped: wifislam was interrupted";
      break;
    default:
      result.status = ProcessResult::Status::kNotStarted;
      result.error = fmt::format("{}: {}", request.argv.front(), std::strerror(report.code));
  }
  return result;
}

std::string file_tail(const std::filesystem::path& file, std::size_t max_lines,
                      std::size_t max_bytes) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return "";
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  const std::streamoff from = size > static_cast<std::streamoff>(max_bytes)
                                  ? size - static_cast<std::streamoff>(max_bytes)
                                  : 0;
  in.seekg(from);
  std::string text(static_cast<std::size_t>(size - from), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  // The last max_lines line starts; the file's last newline ends the last line, not a new one.
  std::size_t start = text.size() > 0 && text.back() == '\n' ? text.size() - 1 : text.size();
  for (std::size_t lines = 0; lines < max_lines && start > 0; ++lines) {
    const std::size_t nl = text.rfind('\n', start - 1);
    if (nl == std::string::npos) return text;
    start = nl;
  }
  return start < text.size() && text[start] == '\n' ? text.substr(start + 1) : text;
}

}  // namespace wifislam::interop
