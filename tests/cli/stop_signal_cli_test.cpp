// Ctrl-C (SIGINT) or SIGTERM while `generate`, `export`, `compare`, `slam`, `study run` or `paper`
// writes its output: the work stops at its next frame and removes <dir>.partial (a study: the
// running case's folder; the paper: the twin's scratch folder), a folder it was replacing stays
// as it was, and the process still ends by the signal. The .partial folder was left behind (a ROS
// bag export: over 100 MB) until a later run into the same path recovered it.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"
#include "tests/support/scratch_folder.hpp"
#include "tests/support/wait_until.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;

class StopSignalCli : public ::testing::Test {
 protected:
  void SetUp() override { scratch_ = test::scratch_folder(); }
  void TearDown() override { fs::remove_all(scratch_); }

  /// `wifislam <args>` run in the background, stderr to `err`; `ignore_hangup` as nohup starts
  /// it. Killed and reaped when the test leaves it running (a failed assertion).
  struct Child {
    pid_t pid = -1;
    int status = 0;
    bool reaped = false;
    ~Child() {
      if (pid > 0 && !reaped) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, &status, 0);
      }
    }
    bool ended() {
      if (!reaped) reaped = ::waitpid(pid, &status, WNOHANG) == pid;
      return reaped;
    }
    void wait() {
      if (!reaped) reaped = ::waitpid(pid, &status, 0) == pid;
    }
  };
  void start(Child& child, const std::vector<std::string>& args, const fs::path& err,
             bool ignore_hangup = false) {
    child.pid = ::fork();
    if (child.pid == 0) {
      if (ignore_hangup) std::signal(SIGHUP, SIG_IGN);
      if (!std::freopen(err.c_str(), "w", stderr)) ::_exit(127);
      std::vector<char*> argv{const_cast<char*>(WIFISLAM_BINARY)};
      for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
      argv.push_back(nullptr);
      ::execv(WIFISLAM_BINARY, argv.data());
      ::_exit(127);
    }
  }
  /// Waits until `partial` exists (the work is under way) or the child ended.
  static bool writing(Child& child, const fs::path& partial) {
    test::wait_until(
        std::chrono::seconds(60), [&] { return fs::exists(partial) || child.ended(); },
        std::chrono::milliseconds(5));
    return fs::exists(partial) && !child.reaped;
  }

  /// Starts the command, waits until `ready()` holds (`what` says when that is), sends `signal`
  /// and checks that the process ended by it and said that it removed its unfinished output.
  void stop_when(const std::vector<std::string>& args, const std::function<bool()>& ready,
                 const char* what, int signal) {
    const fs::path err = scratch_ / "stderr.txt";
    Child child;
    start(child, args, err);
    ASSERT_GT(child.pid, 0);
    test::wait_until(
        std::chrono::seconds(120), [&] { return ready() || child.ended(); },
        std::chrono::milliseconds(5));
    ASSERT_FALSE(child.reaped) << "ended before " << what << ": " << test::read_file(err);
    ASSERT_TRUE(ready()) << "never " << what << ": " << test::read_file(err);
    ASSERT_EQ(::kill(child.pid, signal), 0);
    child.wait();
    ASSERT_TRUE(WIFSIGNALED(child.status))
        << "ended before the signal came: " << test::read_file(err);
    EXPECT_EQ(WTERMSIG(child.status), signal);
    EXPECT_NE(test::read_file(err).find("the unfinished output was removed"), std::string::npos)
        << test::read_file(err);
  }

  /// stop_when the command has started writing `partial`; then `partial` must be gone.
  void stop_while_writing(const std::vector<std::string>& args, const fs::path& partial,
                          int signal) {
    stop_when(
        args, [&] { return fs::exists(partial); }, "it started writing", signal);
    EXPECT_FALSE(fs::exists(partial)) << partial;
  }

  /// Whether a folder in `parent` holds `file` (a dataset among several being generated).
  static bool some_folder_holds(const fs::path& parent, const fs::path& file) {
    std::error_code ec;
    for (const auto& d : fs::directory_iterator(parent, ec))
      if (fs::exists(d.path() / file)) return true;
    return false;
  }

  fs::path scratch_;
};

TEST_F(StopSignalCli, GenerateStoppedRemovesItsPartialFolderAndKeepsTheOneItWasReplacing) {
  const std::string scene = std::string(WIFISLAM_SCENES_DIR) + "/a_hall.yaml";
  const fs::path ds = scratch_ / "ds";
  const auto first = test::run_wifislam(
      "generate " + scene + " -o " + ds.string() + " --fps 2 --max-frames 2 -q", scratch_);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const std::string manifest = test::read_file(ds / "manifest.json");
  stop_while_writing({"generate", scene, "-o", ds.string(), "--fps", "10", "--max-frames", "2000",
                      "--force", "-q"},
                     scratch_ / "ds.partial", SIGINT);
  EXPECT_EQ(test::read_file(ds / "manifest.json"), manifest);
  EXPECT_EQ(test::run_wifislam("check " + ds.string(), scratch_).exit_code, 0);
}

// A signal the caller ignores stays ignored: under nohup, the hangup that closing the terminal
// sends must not stop the run (the guard took it over and removed the dataset).
TEST_F(StopSignalCli, AHangupIgnoredAsNohupDoesIsStillIgnored) {
  const std::string scene = std::string(WIFISLAM_SCENES_DIR) + "/a_hall.yaml";
  const fs::path ds = scratch_ / "ds", err = scratch_ / "stderr.txt";
  Child child;
  start(child, {"generate", scene, "-o", ds.string(), "--fps", "10", "--max-frames", "60", "-q"},
        err, true);
  ASSERT_GT(child.pid, 0);
  ASSERT_TRUE(writing(child, scratch_ / "ds.partial")) << test::read_file(err);
  ASSERT_EQ(::kill(child.pid, SIGHUP), 0);
  child.wait();
  ASSERT_TRUE(WIFEXITED(child.status)) << test::read_file(err);
  EXPECT_EQ(WEXITSTATUS(child.status), 0) << test::read_file(err);
  EXPECT_EQ(test::run_wifislam("check " + ds.string(), scratch_).exit_code, 0);
}

TEST_F(StopSignalCli, ExportStoppedLeavesNothing) {
  const std::string scene = std::string(WIFISLAM_SCENES_DIR) + "/a_hall.yaml";
  const fs::path ds = scratch_ / "ds";
  const auto made = test::run_wifislam(
      "generate " + scene + " -o " + ds.string() + " --fps 5 --max-frames 400 -q", scratch_);
  ASSERT_EQ(made.exit_code, 0) << made.err;
  stop_while_writing(
      {"export", ds.string(), "--for", "rosbag", "-q", "-o", (scratch_ / "bag").string()},
      scratch_ / "bag.partial", SIGTERM);
  EXPECT_FALSE(fs::exists(scratch_ / "bag"));
  stop_while_writing(
      {"export", ds.string(), "--for", "kapture", "-q", "-o", (scratch_ / "kapture").string()},
      scratch_ / "kapture.partial", SIGINT);
  EXPECT_FALSE(fs::exists(scratch_ / "kapture"));
}

// compare (and the demo, the same code): stopped while its dataset is rendered and a run is fed
// from it, and again once the dataset is done and the Wi-Fi run goes on alone (a second rendering
// in memory). Both left <dir>.partial: the demo's was 224 MB.
TEST_F(StopSignalCli, CompareStoppedWhileRenderingOrRunningLeavesNothing) {
  const std::string scene = std::string(WIFISLAM_SCENES_DIR) + "/a_hall.yaml";
  const std::vector<std::string> args = {
      "compare", scene,        "--fps", "5",  "--max-frames",
      "150",     "--no-plots", "-q",    "-o", (scratch_ / "c").string()};
  stop_while_writing(args, scratch_ / "c.partial", SIGINT);
  EXPECT_FALSE(fs::exists(scratch_ / "c"));

  // The dataset is finished (its manifest written) while the second run has its frames to go.
  stop_when(
      args, [&] { return some_folder_holds(scratch_ / "c.partial" / "datasets", "manifest.json"); },
      "its dataset was done", SIGTERM);
  EXPECT_FALSE(fs::exists(scratch_ / "c.partial"));
  EXPECT_FALSE(fs::exists(scratch_ / "c"));
}

// `paper` stopped (Ctrl-C, or scancel's SIGTERM) once a twin's rendering is done and its runs go
// on: the twin's scratch folder (its dataset and runs) goes, the paper folder stays for a rerun.
// The scratch folder stayed until a rerun (170 MB for C Hall at 1 fps), the signal's default
// action ending the process where it stood.
TEST_F(StopSignalCli, PaperStoppedWhileATwinRunsRemovesItsScratchFolderAndKeepsThePaperFolder) {
  const fs::path dir = scratch_ / "p";
  stop_when(
      {"paper", "-o", dir.string(), "--parts", "orbslam", "--twins", "a_hall", "--fps", "1",
       "--jobs", "1", "-q"},
      [&] { return some_folder_holds(dir / "work", fs::path("dataset") / "manifest.json"); },
      "its twin's dataset was done", SIGTERM);
  EXPECT_TRUE(fs::is_empty(dir / "work")) << "the twin's scratch folder is left";
  EXPECT_TRUE(fs::is_regular_file(dir / "paper.json")) << "the folder a rerun continues";
}

// `study run` stopped (Ctrl-C, or the SIGTERM of Slurm's scancel) while a SLAM case renders and
// runs in <database>.work/<case>/: that folder goes, and the database stays for a rerun to resume.
// Before, the case's datasets and runs stayed until a rerun of the same study replaced them.
TEST_F(StopSignalCli, StudyRunStoppedInACaseRemovesTheCasesFolderAndKeepsTheDatabase) {
  const fs::path file = scratch_ / "long_case.yaml", db = scratch_ / "study.sqlite";
  test::write_file(file, "version: 1\nname: long_case\nscene: " + std::string(WIFISLAM_SCENES_DIR) +
                             "/a_hall.yaml\nlevel: slam\naxes:\n  seed: [1]\nslam: {fps: 5}\n");
  stop_while_writing({"study", "run", file.string(), "-q", "-o", db.string()},
                     fs::path(db.string() + ".work"), SIGTERM);
  EXPECT_TRUE(fs::is_regular_file(db)) << "the database a rerun resumes from";
  const auto cases = test::run_wifislam(
      "study merge " + db.string() + " -o " + (scratch_ / "merged.sqlite").string(), scratch_);
  EXPECT_EQ(cases.exit_code, 0) << cases.err;
  EXPECT_NE(cases.err.find("0 of the study's 1 cases"), std::string::npos) << cases.err;
}

// `study run` of an external system stopped while the system's run is being scored: the stop was
// taken for the run's own failure ("not scorable: stopped by SIGTERM"), the case was stored as
// finished with no numbers, and a rerun skipped it. The system pads its trajectory with 3 million
// poses past the route's end, so that scoring takes seconds and the stop lands in it.
TEST_F(StopSignalCli, StudyRunStoppedWhileARunIsScoredStoresNoRowForTheCase) {
  const fs::path system = scratch_ / "padded.yaml", db = scratch_ / "study.sqlite";
  test::write_file(scratch_ / "padded.sh",
                   "cp \"$1/groundtruth.txt\" \"$2/trajectory.txt\"\n"
                   "tail -n 1 \"$1/groundtruth.txt\" | awk '{for (i = 1; i <= 3000000; i++) "
                   "printf \"%.6f %s %s %s %s %s %s %s\\n\", $1 + i * 1e-6, $2, $3, $4, $5, $6, "
                   "$7, $8}' >> \"$2/trajectory.txt\"\n");
  test::write_file(system,
                   "version: 1\nname: padded\ncommand: [/bin/sh, \"{system_dir}/padded.sh\", "
                   "\"{dataset}\", \"{out}\"]\nwifi: false\n"
                   "outputs: {trajectory: trajectory.txt}\n");
  const fs::path file = scratch_ / "external.yaml";
  test::write_file(file, "version: 1\nname: external\nscene: " + std::string(WIFISLAM_SCENES_DIR) +
                             "/a_hall.yaml\nlevel: slam\naxes:\n  system: [" + system.string() +
                             "]\nslam: {fps: 3, max_frames: 10}\n");
  const fs::path err = scratch_ / "stderr.txt";
  Child child;
  start(child, {"study", "run", file.string(), "-q", "-o", db.string()}, err);
  ASSERT_GT(child.pid, 0);
  // The run folder is in place (its run.json written last) and its scoring under way.
  const auto run_in_place = [&] {
    std::error_code ec;
    for (fs::recursive_directory_iterator it(db.string() + ".work", ec), end; !ec && it != end;
         it.increment(ec))
      if (it->path().filename() == "run.json" && it->path().parent_path().filename() == "vanilla")
        return true;
    return false;
  };
  test::wait_until(
      std::chrono::seconds(120), [&] { return run_in_place() || child.ended(); },
      std::chrono::milliseconds(5));
  ASSERT_FALSE(child.reaped) << "ended before its run was scored: " << test::read_file(err);
  ASSERT_EQ(::kill(child.pid, SIGTERM), 0);
  child.wait();
  ASSERT_TRUE(WIFSIGNALED(child.status)) << "ended before the signal: " << test::read_file(err);
  EXPECT_EQ(WTERMSIG(child.status), SIGTERM);
  EXPECT_FALSE(fs::exists(db.string() + ".work"));
  const auto merged = test::run_wifislam(
      "study merge " + db.string() + " -o " + (scratch_ / "merged.sqlite").string(), scratch_);
  EXPECT_NE(merged.err.find("0 of the study's 1 cases"), std::string::npos)
      << "the stopped case was stored: " << merged.err;
}

// An external system compare waits for: SIGTERM to wifislam used to end it and, through the
// kernel, the system's supervisor; under the stop guard wifislam lives on, so it passes the stop
// on. Without that it waited for the system (here 300 s) before it stopped.
TEST_F(StopSignalCli, CompareStoppedWhileAnExternalSystemRunsStopsTheSystemToo) {
  const std::string scene = std::string(WIFISLAM_SCENES_DIR) + "/a_hall.yaml";
  const fs::path system = scratch_ / "sleeper.yaml", pid_file = scratch_ / "system.pid";
  test::write_file(system,
                   "version: 1\nname: sleeper\ndescription: stands still until stopped\n"
                   "command: [/bin/sh, -c, 'echo $$ > " +
                       pid_file.string() +
                       "; exec sleep 300']\nwifi: false\n"
                       "outputs: {trajectory: trajectory.txt}\n");
  const fs::path err = scratch_ / "stderr.txt";
  Child child;
  start(child,
        {"compare", scene, "--frontend", "external:" + system.string(), "--max-frames", "6",
         "--no-plots", "-q", "-o", (scratch_ / "c").string()},
        err);
  ASSERT_GT(child.pid, 0);
  test::wait_until(
      std::chrono::seconds(120),
      [&] { return !test::read_file_if_present(pid_file).empty() || child.ended(); },
      std::chrono::milliseconds(5));
  ASSERT_FALSE(child.reaped) << "ended before its system started: " << test::read_file(err);
  const pid_t system_pid = std::stoi(test::read_file(pid_file));
  ASSERT_EQ(::kill(child.pid, SIGTERM), 0);
  EXPECT_TRUE(test::wait_until(
      std::chrono::seconds(60), [&] { return child.ended(); }, std::chrono::milliseconds(5)))
      << "still waiting for its system";
  child.wait();
  ASSERT_TRUE(WIFSIGNALED(child.status)) << test::read_file(err);
  EXPECT_EQ(WTERMSIG(child.status), SIGTERM);
  EXPECT_FALSE(fs::exists(scratch_ / "c.partial"));
  EXPECT_FALSE(fs::exists(scratch_ / "c"));
  EXPECT_NE(::kill(system_pid, 0), 0) << "the system outlived the run";
}

}  // namespace
}  // namespace wifislam
