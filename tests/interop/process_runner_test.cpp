// interop/process_runner: another program run with no shell, its output in files, its exit, signal,
// timeout and working folder reported as they happened (real child processes).
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "interop/process_runner.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::interop {
namespace {

namespace fs = std::filesystem;

class ProcessRunner : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::scratch_folder(); }

  ProcessResult run(std::vector<std::string> argv, double timeout_s = 60.0) {
    ProcessRequest request;
    request.argv = std::move(argv);
    request.working_dir = dir_;
    request.stdout_file = dir_ / "out.txt";
    request.stderr_file = dir_ / "err.txt";
    request.timeout_s = timeout_s;
    return run_process(request);
  }
  std::string read(const std::string& name) const {
    std::ifstream in(dir_ / name);
    return {(std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()};
  }

  fs::path dir_;
};

TEST_F(ProcessRunner, ExitCodeAndBothStreamsAreKept) {
  const ProcessResult r = run({"/bin/sh", "-c", "echo out; echo err >&2; exit 3"});
  EXPECT_EQ(r.status, ProcessResult::Status::kExited);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_FALSE(r.succeeded());
  EXPECT_EQ(r.describe(60), "exited 3");
  EXPECT_EQ(read("out.txt"), "out\n");
  EXPECT_EQ(read("err.txt"), "err\n");
  EXPECT_TRUE(run({"true"}).succeeded()) << "a bare name is looked up in PATH";
}

TEST_F(ProcessRunner, ArgumentsReachTheProgramAsTheyAreWithNoShell) {
  const ProcessResult r = run({"/bin/echo", "a; rm -rf b", "$HOME", "*"});
  ASSERT_TRUE(r.succeeded()) << r.describe(60);
  EXPECT_EQ(read("out.txt"), "a; rm -rf b $HOME *\n");
}

TEST_F(ProcessRunner, RunsInTheWorkingFolderWithNothingOnStdin) {
  ASSERT_TRUE(run({"/bin/sh", "-c", "pwd; cat"}).succeeded());
  EXPECT_EQ(read("out.txt"), fs::canonical(dir_).string() + "\n");
}

TEST_F(ProcessRunner, AMissingProgramIsNotStartedAndSaysWhy) {
  const ProcessResult r = run({(dir_ / "no_such_program").string()});
  EXPECT_EQ(r.status, ProcessResult::Status::kNotStarted);
  EXPECT_FALSE(r.error.empty());
  EXPECT_NE(r.describe(60).find("not started"), std::string::npos) << r.describe(60);
}

TEST_F(ProcessRunner, ASignalIsReportedAsSuch) {
  const ProcessResult r = run({"/bin/sh", "-c", "kill -SEGV $$"});
  EXPECT_EQ(r.status, ProcessResult::Status::kSignalled);
  EXPECT_EQ(r.signal, SIGSEGV);
  EXPECT_EQ(r.describe(60), "killed by signal 11 (Segmentation fault)");
}

TEST_F(ProcessRunner, ATimeoutStopsTheProgramAndWhatItStarted) {
  const auto start = std::chrono::steady_clock::now();
  const ProcessResult r = run({"/bin/sh", "-c", "sleep 300 & sleep 300"}, 0.5);
  const double waited_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.status, ProcessResult::Status::kTimedOut);
  EXPECT_NE(r.describe(0.5).find("timed out"), std::string::npos) << r.describe(0.5);
  EXPECT_LT(waited_s, 10.0) << "the run outlived its timeout by far";
  EXPECT_GE(r.wall_s, 0.5);
}

TEST_F(ProcessRunner, FileTailKeepsTheLastLines) {
  {
    std::ofstream out(dir_ / "log.txt");
    for (int i = 1; i <= 30; ++i) out << "line " << i << "\n";
  }
  const std::string tail = file_tail(dir_ / "log.txt", 3);
  EXPECT_EQ(tail, "line 28\nline 29\nline 30\n");
  EXPECT_EQ(file_tail(dir_ / "missing.txt"), "");
}

}  // namespace
}  // namespace wifislam::interop
