#include "peers/process_runner.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <thread>

#include <fmt/format.h>

#include "core/wall_clock.hpp"

extern char** environ;

namespace wifislam::peers {

namespace {

double cpu_seconds(const rusage& usage) {
  const auto seconds = [](const timeval& t) { return t.tv_sec + 1e-6 * t.tv_usec; };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

/// Waits for `pid` until `deadline`; true when it ended (status and usage filled, or `lost` set
/// when the child cannot be waited for: its status is then unknown, never a success).
bool wait_until(pid_t pid, WallClock::time_point deadline, int& status, rusage& usage, bool& lost) {
  while (true) {
    const pid_t done = ::wait4(pid, &status, WNOHANG, &usage);
    if (done == pid) return true;
    if (done < 0 && errno != EINTR) {
      lost = true;
      return true;
    }
    if (WallClock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
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
  std::vector<char*> argv;
  for (const std::string& a : request.argv) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, request.stdout_file.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, request.stderr_file.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addchdir_np(&actions, request.working_dir.c_str());
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);  // its own group: a timeout stops its children too

  const auto start = WallClock::now();
  pid_t pid = 0;
  const bool by_path = request.argv.front().find('/') == std::string::npos;
  const int spawned =
      by_path ? ::posix_spawnp(&pid, argv[0], &actions, &attributes, argv.data(), environ)
              : ::posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (spawned != 0) {
    result.error = fmt::format("{}: {}", request.argv.front(), std::strerror(spawned));
    return result;
  }

  int status = 0;
  rusage usage{};
  const auto deadline = start + std::chrono::duration_cast<WallClock::duration>(
                                    std::chrono::duration<double>(request.timeout_s));
  bool timed_out = false, lost = false;
  if (!wait_until(pid, deadline, status, usage, lost)) {
    timed_out = true;
    ::kill(-pid, SIGTERM);
    if (!wait_until(pid, WallClock::now() + std::chrono::seconds(2), status, usage, lost)) {
      ::kill(-pid, SIGKILL);
      ::wait4(pid, &status, 0, &usage);
    }
  }
  ::kill(-pid, SIGKILL);  // whatever it left running in its group
  result.wall_s = seconds_since(start);
  result.cpu_s = cpu_seconds(usage);
  if (timed_out) {
    result.status = ProcessResult::Status::kTimedOut;
  } else if (lost) {
    result.status = ProcessResult::Status::kLost;
    result.error = std::string("wait4: ") + std::strerror(errno);
  } else if (WIFEXITED(status)) {
    result.status = ProcessResult::Status::kExited;
    result.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.status = ProcessResult::Status::kSignalled;
    result.signal = WTERMSIG(status);
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

}  // namespace wifislam::peers
