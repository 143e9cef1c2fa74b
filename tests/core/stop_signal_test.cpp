// StopOnSignal (core/stop_signal.hpp): a signal under the guard is recorded, not acted on, and
// the work sees it at its next check; one that came after the last check ends the process when
// the guard goes, by that signal, after what the command printed has gone out (stdout to a pipe
// is block-buffered: `paper | tee log` lost its verdicts when stopped during the report).
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "core/stop_signal.hpp"

namespace wifislam {
namespace {

/// Runs `body` in a child whose stdout is a pipe; returns what it printed and its wait status.
template <class Body>
std::pair<std::string, int> in_child_with_piped_stdout(Body body) {
  int fds[2];
  EXPECT_EQ(::pipe(fds), 0);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(fds[1], STDOUT_FILENO);
    ::close(fds[0]);
    ::close(fds[1]);
    body();
    std::fflush(stdout);
    ::_exit(0);
  }
  ::close(fds[1]);
  std::string out;
  char buffer[256];
  for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) > 0;) out.append(buffer, n);
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return {out, status};
}

TEST(StopOnSignal, ASignalUnderTheGuardIsSeenAtTheNextCheck) {
  const auto [out, status] = in_child_with_piped_stdout([] {
    const StopOnSignal guard;
    std::raise(SIGTERM);  // recorded: the process goes on
    std::printf("still running; ");
    try {
      throw_if_stop_requested();
    } catch (const StoppedBySignal& e) {
      std::printf("stopped by %d", e.signal());
      std::fflush(stdout);
      ::_exit(3);
    }
  });
  ASSERT_TRUE(WIFEXITED(status)) << out;
  EXPECT_EQ(WEXITSTATUS(status), 3);
  EXPECT_EQ(out, "still running; stopped by " + std::to_string(SIGTERM));
}

TEST(StopOnSignal, ASignalAfterTheLastCheckEndsTheProcessWhenTheGuardGoesOutputFlushed) {
  const auto [out, status] = in_child_with_piped_stdout([] {
    const StopOnSignal guard;
    std::printf("report written");  // buffered: stdout is a pipe
    std::raise(SIGINT);
  });
  ASSERT_TRUE(WIFSIGNALED(status)) << "ended by exit, not by the signal: " << out;
  EXPECT_EQ(WTERMSIG(status), SIGINT);
  EXPECT_EQ(out, "report written");
}

}  // namespace
}  // namespace wifislam
