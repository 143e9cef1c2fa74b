// An external system is contained (issue 44): nothing it starts outlives its run, whether the run
// ends by itself, or wifislam is stopped by SIGINT, SIGTERM or SIGKILL (interop/process_runner.hpp:
// a supervisor that is a child subreaper and hears wifislam's death); its declared outputs are
// never followed out of its folder by a symbolic link; what it does around its folder ends in a
// failed run (exit 5, a run folder, run.json naming paths that exist), never an internal error;
// a system file that is a FIFO with no writer is refused at once.
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/cli/shared_dataset.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"
#include "tests/support/wait_until.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using test::read_file;
using test::write_file;

/// Pids of live (not zombie) processes whose command line holds `needle` as one argument.
std::vector<pid_t> processes_with_argument(const std::string& needle) {
  std::vector<pid_t> out;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    // A process may exit between the listing and the read.
    const std::string cmdline = test::read_file_if_present(entry.path() / "cmdline");
    bool found = false;
    for (std::size_t at = 0; at < cmdline.size();) {
      const std::size_t end = cmdline.find('\0', at);
      if (cmdline.substr(at, end - at) == needle) found = true;
      if (end == std::string::npos) break;
      at = end + 1;
    }
    if (!found) continue;
    const std::string stat = test::read_file_if_present(entry.path() / "stat");
    const std::size_t close = stat.rfind(')');
    if (close != std::string::npos && close + 2 < stat.size() && stat[close + 2] == 'Z') continue;
    out.push_back(static_cast<pid_t>(std::stol(name)));
  }
  return out;
}

class ExternalContainment : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dataset_ = test::shared_tiny_wifi_dataset("--no-images");
    generated_ = !dataset_.empty();
  }
  void SetUp() override {
    ASSERT_TRUE(generated_);
    scratch_ = test::scratch_folder();
  }
  void TearDown() override { fs::remove_all(scratch_); }

  /// A system running `script` as /bin/sh "{system_dir}/x.sh" "{dataset}" "{out}".
  fs::path system_file(const std::string& script, const std::string& outputs,
                       double timeout_s = 60) {
    write_file(scratch_ / "x.sh", script);
    write_file(scratch_ / "system.yaml",
               "version: 1\nname: x\ncommand: [/bin/sh, \"{system_dir}/x.sh\", \"{dataset}\", "
               "\"{out}\"]\ntimeout_s: " +
                   std::to_string(timeout_s) + "\noutputs: " + outputs + "\n");
    return scratch_ / "system.yaml";
  }
  std::string slam_args(const fs::path& system) const {
    return "slam " + dataset_.string() + " -o " + (scratch_ / "run").string() +
           " --frontend external:" + system.string();
  }
  /// A number no other test run uses, as an argument of `sleep`.
  static std::string unique_seconds(int base) {
    return std::to_string(base) + "." + std::to_string(::getpid() % 100000);
  }

  static inline fs::path dataset_;
  static inline bool generated_ = false;
  fs::path scratch_;
};

TEST_F(ExternalContainment, WhatTheSystemStartedIsGoneWhenItsRunEndsSetsidIncluded) {
  const std::string seconds = unique_seconds(3142);
  const fs::path system =
      system_file("cp \"$1/groundtruth.txt\" \"$2/trajectory.txt\"\nsetsid sleep " + seconds +
                      " &\nsleep " + seconds + "1 &\nsleep 1\nexit 0\n",
                  "{trajectory: trajectory.txt}");
  const test::CliResult r = test::run_wifislam(slam_args(system), scratch_);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(processes_with_argument(seconds).empty()) << "the setsid'd sleep outlived the run";
  EXPECT_TRUE(processes_with_argument(seconds + "1").empty()) << "a background sleep outlived it";
}

/// wifislam stopped by `signal` while its system sleeps: the sleep must not survive it.
void expect_system_dies_with_wifislam(const std::string& args, const fs::path& scratch,
                                      const std::string& seconds, int signal) {
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::setpgid(0, 0);  // our own group: the signal goes to wifislam alone
    const std::string command = "exec " + std::string(WIFISLAM_BINARY) + " " + args + " >'" +
                                (scratch / "out.txt").string() + "' 2>&1";
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const bool started = test::wait_until(std::chrono::seconds(30),
                                        [&] { return !processes_with_argument(seconds).empty(); });
  ASSERT_TRUE(started) << test::read_file(scratch / "out.txt");
  ::kill(pid, signal);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status)) << test::read_file(scratch / "out.txt");
  EXPECT_EQ(WTERMSIG(status), signal);
  if (signal != SIGKILL) {
    // `slam`'s stop guard: the system is stopped in turn and the unfinished run folder removed.
    EXPECT_FALSE(fs::exists(scratch / "run.partial")) << test::read_file(scratch / "out.txt");
    EXPECT_NE(test::read_file(scratch / "out.txt").find("the unfinished output was removed"),
              std::string::npos)
        << test::read_file(scratch / "out.txt");
  }
  EXPECT_TRUE(test::wait_until(std::chrono::seconds(10),
                               [&] { return processes_with_argument(seconds).empty(); }))
      << "the system's sleep outlived wifislam stopped by signal " << signal;
  for (pid_t left : processes_with_argument(seconds)) ::kill(left, SIGKILL);  // never leak it
}

TEST_F(ExternalContainment, StoppingWifislamStopsItsSystem) {
  int round = 0;
  for (int signal : {SIGINT, SIGTERM, SIGKILL}) {
    SCOPED_TRACE(::strsignal(signal));
    const std::string seconds = unique_seconds(2718 + round++);
    const fs::path system =
        system_file("sleep " + seconds + "\n", "{trajectory: trajectory.txt}", 60);
    fs::remove_all(scratch_ / "run");
    fs::remove_all(scratch_ / "run.partial");
    expect_system_dies_with_wifislam(slam_args(system), scratch_, seconds, signal);
  }
}

TEST_F(ExternalContainment, OutputsAreNeverFollowedOutOfTheSystemsFolder) {
  struct Case {
    std::string script, outputs, why;
  };
  const std::vector<Case> cases = {
      {"cp \"$1/groundtruth.txt\" \"$2/t.txt\"\nln -s /etc/passwd \"$2/graph.json\"\n"
       "cp \"$1/groundtruth.txt\" \"$2/k.txt\"\n",
       "{trajectory: t.txt, keyframes: k.txt, graph: graph.json}", "symbolic link"},
      {"ln -s \"$1/groundtruth.txt\" \"$2/trajectory.txt\"\n", "{trajectory: trajectory.txt}",
       "symbolic link"},
      {"mkdir -p \"$2/../elsewhere\"\ncp \"$1/groundtruth.txt\" \"$2/../elsewhere/trajectory.txt\""
       "\nln -s \"$2/../elsewhere\" \"$2/run\"\n",
       "{trajectory: run/trajectory.txt}", "symbolic link"},
      {"mkfifo \"$2/trajectory.txt\"\n", "{trajectory: trajectory.txt}", "not a regular file"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.script);
    fs::remove_all(scratch_ / "run");
    const test::CliResult r =
        test::run_wifislam(slam_args(system_file(c.script, c.outputs)), scratch_);
    EXPECT_EQ(r.exit_code, 5) << r.err;
    EXPECT_NE(r.err.find(c.why), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(scratch_ / "run" / "trajectory.txt"));
    EXPECT_FALSE(fs::exists(scratch_ / "run" / "graph.json"));
    const nlohmann::json run =
        nlohmann::json::parse(test::read_file(scratch_ / "run" / "run.json"));
    const std::string status = run.at("external").at("status").get<std::string>();
    EXPECT_NE(status.find(c.why), std::string::npos) << status;
    EXPECT_EQ(status.find(".partial"), std::string::npos) << "a path that no longer exists";
  }
}

TEST_F(ExternalContainment, WhatTheSystemDoesAroundItsFolderIsItsFailureNotOurs) {
  for (const std::string& mischief :
       {std::string("mkdir -p \"$2/../trajectory.txt/keep\""),
        std::string("mkdir -p \"$2/../timing.json/x\""), std::string("mkdir \"$2/../run.json\""),
        std::string("rm -rf \"$(dirname \"$2\")\"")}) {
    SCOPED_TRACE(mischief);
    fs::remove_all(scratch_ / "run");
    const fs::path system =
        system_file("cp \"$1/groundtruth.txt\" \"$2/trajectory.txt\"\n" + mischief + "\n",
                    "{trajectory: trajectory.txt}");
    const test::CliResult r = test::run_wifislam(slam_args(system), scratch_);
    // Around {out} there is nothing of ours: the run succeeds, or fails as the system's run
    // (its folder removed), with its run folder; never an internal error or a bad-input exit.
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 5) << r.exit_code << ": " << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::is_regular_file(scratch_ / "run" / "run.json")) << r.err;
  }
}

TEST_F(ExternalContainment, ASystemThatLinksItsFoldersElsewhereMakesUsDeleteNothingThere) {
  // A folder of the user's that the system points the run's folders at: after the run, every
  // file in it is still there. $2/.. is the system's scratch folder, $2/../.. the run folder
  // under construction.
  const fs::path victim = scratch_ / "victim";
  for (const std::string& mischief :
       {std::string("d=\"$(dirname \"$2\")\"; rm -rf \"$d\"; ln -s \"") + victim.string() +
            "\" \"$d\"",
        std::string("d=\"$(dirname \"$(dirname \"$2\")\")\"; mv \"$d\" \"$d.moved\"; ln -s \"") +
            victim.string() + "\" \"$d\""}) {
    SCOPED_TRACE(mischief);
    fs::remove_all(scratch_ / "run");
    fs::remove_all(victim);
    fs::create_directories(victim / "out" / "keep");
    for (const char* f : {"trajectory.txt", "graph.json", "run", "thesis.tex", "out/x"})
      std::ofstream(victim / f) << "mine\n";
    const fs::path system =
        system_file("cp \"$1/groundtruth.txt\" \"$2/trajectory.txt\"\n" + mischief + "\n",
                    "{trajectory: trajectory.txt}");
    const test::CliResult r = test::run_wifislam(slam_args(system), scratch_);
    EXPECT_NE(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
    for (const char* f : {"trajectory.txt", "graph.json", "run", "thesis.tex", "out/x"})
      EXPECT_EQ(test::read_file(victim / f), "mine\n") << f;
    EXPECT_TRUE(fs::is_directory(victim / "out" / "keep"));
  }
}

// compare (and study run) write each run's evaluation into <run>/eval after the system ran: a link
// the system left there made that evaluation replace the folder it named, a finished output of
// ours anywhere on disk, with its notes.
TEST_F(ExternalContainment, AnEvalLinkTheSystemLeavesIsNeverFollowed) {
  const fs::path victim = scratch_ / "victim";
  fs::create_directories(victim);
  write_file(victim / ".wifislam-output", "a finished output of ours\n");
  write_file(victim / "notes.txt", "mine\n");
  const fs::path system = system_file("cp \"$1/groundtruth.txt\" \"$2/trajectory.txt\"\nln -s \"" +
                                          victim.string() + "\" \"$2/../../eval\"\n",
                                      "{trajectory: trajectory.txt}");
  const test::CliResult r = test::run_wifislam(
      "compare " + std::string(WIFISLAM_SCENES_DIR) + "/a_hall.yaml --frontend external:" +
          system.string() + " --fps 3 --max-frames 4 --no-plots -q -o " + (scratch_ / "c").string(),
      scratch_);
  EXPECT_EQ(read_file(victim / "notes.txt"), "mine\n") << r.err;
  EXPECT_FALSE(fs::exists(victim / "metrics.json")) << "the evaluation went through the link";
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST_F(ExternalContainment, AFifoSystemFileIsRefusedAtOnce) {
  const fs::path fifo = scratch_ / "system.yaml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  const auto start = Clock::now();
  const test::CliResult r = test::run_wifislam(slam_args(fifo), scratch_);
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - start).count(), 30.0);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(fifo.string()), std::string::npos) << r.err;
}

TEST_F(ExternalContainment, AnOutputThatIsTheSystemsFolderIsRefusedWhenTheFileIsRead) {
  const test::CliResult r =
      test::run_wifislam(slam_args(system_file("exit 0\n", "{trajectory: .}")), scratch_);
  test::expect_located_bad_input(r, (scratch_ / "system.yaml").string() + ":",
                                 "outputs.trajectory");
  EXPECT_FALSE(fs::exists(scratch_ / "run"));
}

}  // namespace
}  // namespace wifislam
