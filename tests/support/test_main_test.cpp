// The suites' main (test_main.cpp): a test process that dies of a signal names the test that was
// running and prints a backtrace with the executable's frames named, and still dies of that signal,
// so ctest reports the crash.

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <csignal>
#include <cstdlib>
#include <string>

#include "tests/support/read_file.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam {
namespace {

TEST(TestMain, ACrashedTestIsNamedWithABacktraceAndTheProcessDiesOfItsSignal) {
  const std::filesystem::path err = test::scratch_folder() / "stderr.txt";
  // exec: the status is the probe's own, not a shell's exit code for it.
  const std::string command =
      std::string("exec ") + WIFISLAM_CRASHING_TEST_PROBE + " 2>'" + err.string() + "' >/dev/null";
  const int status = std::system(command.c_str());
  const std::string printed = test::read_file(err);
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer keeps its own report of the signal (test_main.cpp), and exits with 1.
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) != 0) << "status " << status;
  EXPECT_NE(printed.find("AddressSanitizer: SEGV"), std::string::npos) << printed;
#else
  ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status << "\n" << printed;
  EXPECT_EQ(WTERMSIG(status), SIGSEGV);
  EXPECT_NE(printed.find("*** fatal signal SIGSEGV (segmentation fault) in test "
                         "CrashingProbe.DiesOfASegmentationFault; backtrace"),
            std::string::npos)
      << printed;
  // The probe's own frames, as offsets, then named by addr2line: the handler, GoogleTest's.
  EXPECT_NE(printed.find("crashing_test_probe(+0x"), std::string::npos) << printed;
  const std::size_t named = printed.find("the executable's frames, named by addr2line");
  ASSERT_NE(named, std::string::npos) << printed;
  EXPECT_NE(printed.find("report_fatal_signal", named), std::string::npos) << printed;
  EXPECT_NE(printed.find("testing::Test::Run()", named), std::string::npos) << printed;
#endif
}

}  // namespace
}  // namespace wifislam
