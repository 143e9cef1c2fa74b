// llvmpipe's rendering threads do not survive fork(): a child forked after its parent created an
// OpenGL context waited for them for ever at its first draw (Python's multiprocessing forks by
// default). Such a child now gets EnvironmentError, for the inherited context and for a new one,
// and the parent renders on.

#include <gtest/gtest.h>

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>

#include "core/error.hpp"
#include "sim/render/osmesa_context.hpp"

namespace wifislam::sim {
namespace {

// What the child found, one bit a failure; 0 when every check held.
int check_in_forked_child(render::OsmesaContext& inherited) {
  int failures = 0;
  if (render::OsmesaContext::usable_in_this_process()) failures |= 1;
  try {
    inherited.make_current();
    failures |= 2;
  } catch (const EnvironmentError& e) {
    if (std::string(e.what()).find("forked") == std::string::npos) failures |= 4;
  }
  try {
    render::OsmesaContext fresh;
    failures |= 8;
  } catch (const EnvironmentError& e) {
    if (std::string(e.what()).find("spawn") == std::string::npos) failures |= 16;
  }
  return failures;
}

TEST(OsmesaContextFork, AChildForkedAfterAContextExistsIsRefusedNotLeftHanging) {
  render::OsmesaContext context;  // starts llvmpipe in this process
  ASSERT_TRUE(render::OsmesaContext::usable_in_this_process());
  // The child holds the write end of a pipe until it exits: poll() on the read end wakes when
  // the child is gone, or gives up after a minute, since a hang is the failure this test catches.
  int exited[2];
  ASSERT_EQ(::pipe(exited), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::close(exited[0]);
    ::_exit(check_in_forked_child(context));  // no gtest, no destructors there
  }
  ::close(exited[1]);
  pollfd end{exited[0], POLLIN, 0};
  const int ready = ::poll(&end, 1, 60'000);
  ::close(exited[0]);
  int status = 0;
  if (ready == 0) {
    ::kill(child, SIGKILL);
    ::waitpid(child, &status, 0);
    FAIL() << "the forked child hung";
  }
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the forked child died of a signal";
  EXPECT_EQ(WEXITSTATUS(status), 0) << "failed checks (bits): " << WEXITSTATUS(status);
  EXPECT_NO_THROW(context.make_current());  // the parent's context works on
  EXPECT_TRUE(render::OsmesaContext::usable_in_this_process());
}

}  // namespace
}  // namespace wifislam::sim
