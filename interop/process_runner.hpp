#pragma once
// Runs another program as a child process, the way external systems run (external_run.hpp): no
// shell (the arguments are passed as they are), a working folder of the caller's choosing, stdin
// from /dev/null, stdout and stderr into files, in a process group of its own so that a timeout
// stops the program and everything it started, and its wall-clock and CPU time measured.

#include <filesystem>
#include <string>
#include <vector>

namespace wifislam::interop {

struct ProcessRequest {
  /// argv[0] is a path when it holds a '/', else it is looked up in PATH.
  std::vector<std::string> argv;
  std::filesystem::path working_dir;
  std::filesystem::path stdout_file, stderr_file;  // created (truncated)
  /// After this long the process group gets SIGTERM, and SIGKILL two seconds later.
  double timeout_s = 3600.0;
};

struct ProcessResult {
  enum class Status {
    kExited,      // exit_code holds the exit status
    kSignalled,   // killed by `signal` (not by us)
    kTimedOut,    // we stopped it after timeout_s
    kNotStarted,  // it could not be started (`error` says why: no such program, not executable)
    kLost,        // it ran but could not be waited for (`error` says why): never a success
  };
  Status status = Status::kNotStarted;
  int exit_code = -1;
  int signal = 0;
  double wall_s = 0.0;
  double cpu_s = 0.0;  // user + system time of the process and the children it waited for
  std::string error;
  bool succeeded() const { return status == Status::kExited && exit_code == 0; }
  /// "exited 0", "exited 3", "killed by signal 11", "timed out after 60 s", "not started: ..."
  std::string describe(double timeout_s) const;
};

ProcessResult run_process(const ProcessRequest& request);

/// The last `max_lines` lines (at most `max_bytes`) of a text file, for reports; "" when
/// unreadable.
std::string file_tail(const std::filesystem::path& file, std::size_t max_lines = 20,
                      std::size_t max_bytes = 4096);

}  // namespace wifislam::interop
