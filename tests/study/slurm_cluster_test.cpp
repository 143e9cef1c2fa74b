// A study on a real Slurm cluster: this test starts a one-node cluster of its own in a scratch
// folder (munged with its own socket and key, slurmctld and slurmd on ports of its own, found
// through SLURM_CONF, so nothing of the machine's is read or changed), submits a radio-level study
// as a 4-task job array with its dependent merge job through `wifislam study slurm --submit`,
// waits for the merged database (5 minutes at most) and checks it equals the unsharded run row
// for row. It stops exactly the three daemons it started, also when a check fails.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <pwd.h>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "study/result_store.hpp"
#include "study/study_file.hpp"
#include "study/study_runner.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"
#include "tests/support/wait_until.hpp"

namespace wifislam::study {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string find_program(const std::string& name) {
  for (const char* dir : {"/usr/sbin", "/usr/bin", "/sbin", "/bin"}) {
    const fs::path p = fs::path(dir) / name;
    if (::access(p.c_str(), X_OK) == 0) return p.string();
  }
  return "";
}

std::string short_hostname() {
  char name[256] = {};
  ::gethostname(name, sizeof name - 1);
  std::string host = name;
  return host.substr(0, host.find('.'));
}

std::string user_name() {
  const passwd* pw = ::getpwuid(::getuid());
  return pw ? pw->pw_name : "root";
}

/// The daemons this test started; stopped (SIGTERM, then SIGKILL) when it goes out of scope.
class Daemons {
 public:
  ~Daemons() { stop(); }
  /// Starts `argv` with `log` as its stdout and stderr, and SLURM_CONF set.
  void start(const std::vector<std::string>& argv, const fs::path& log, const fs::path& conf) {
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      ::setenv("SLURM_CONF", conf.c_str(), 1);
      FILE* out = std::freopen(log.c_str(), "w", stdout);
      if (out) ::dup2(::fileno(stdout), 2);
      std::vector<char*> args;
      for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
      args.push_back(nullptr);
      ::execv(args[0], args.data());
      ::_exit(127);
    }
    pids_.push_back(pid);
  }
  bool all_running() const {
    for (pid_t pid : pids_) {
      int status = 0;
      if (::waitpid(pid, &status, WNOHANG) != 0) return false;
    }
    return true;
  }
  void stop() {
    for (auto it = pids_.rbegin(); it != pids_.rend(); ++it) ::kill(*it, SIGTERM);
    const auto deadline = Clock::now() + std::chrono::seconds(10);
    for (pid_t pid : pids_) {
      int status = 0;
      const bool exited = test::wait_until(deadline - Clock::now(),
                                           [&] { return ::waitpid(pid, &status, WNOHANG) != 0; });
      if (!exited) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, &status, 0);
      }
    }
    pids_.clear();
  }

 private:
  std::vector<pid_t> pids_;
};

std::string slurm_conf(const fs::path& d, const std::string& host, int port,
                       const std::string& user) {
  const std::string dir = d.string();
  return "ClusterName=wifislamtest\n"
         "SlurmctldHost=" +
         host +
         "\n"
         "SlurmctldPort=" +
         std::to_string(port) +
         "\n"
         "SlurmdPort=" +
         std::to_string(port + 1) +
         "\n"
         "SlurmUser=" +
         user + "\nSlurmdUser=" + user +
         "\n"
         "AuthType=auth/munge\nCredType=cred/munge\n"
         "AuthInfo=socket=" +
         dir +
         "/munge/munge.socket\n"
         "StateSaveLocation=" +
         dir + "/state\nSlurmdSpoolDir=" + dir +
         "/spool\n"
         "SlurmctldPidFile=" +
         dir + "/slurmctld.pid\nSlurmdPidFile=" + dir +
         "/slurmd.pid\n"
         "SlurmctldLogFile=" +
         dir + "/log/slurmctld.log\nSlurmdLogFile=" + dir +
         "/log/slurmd.log\n"
         "ProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\n"
         "SelectType=select/cons_tres\nSelectTypeParameters=CR_Core\n"
         "ReturnToService=2\nMpiDefault=none\n"
         "NodeName=" +
         host +
         " CPUs=2 RealMemory=2000 State=UNKNOWN\n"
         "PartitionName=debug Nodes=" +
         host + " Default=YES MaxTime=INFINITE State=UP\n";
}

TEST(SlurmCluster, AStudyAsAFourTaskJobArrayMergesToTheUnshardedRun) {
  const std::string munged = find_program("munged"), slurmctld = find_program("slurmctld"),
                    slurmd = find_program("slurmd");
  ASSERT_FALSE(munged.empty() || slurmctld.empty() || slurmd.empty())
      << "munge and slurm-wlm are not installed (scripts/install-deps.sh installs them)";
  const fs::path dir = test::scratch_folder();
  for (const char* sub : {"munge", "state", "spool", "log"}) fs::create_directories(dir / sub);
  ::chmod((dir / "munge").c_str(), 0700);
  {
    // A key of our own (munged refuses a key others can read).
    std::string key(1024, '\0');
    for (std::size_t i = 0; i < key.size(); ++i) key[i] = static_cast<char>((i * 131 + 7) % 251);
    test::write_file(dir / "munge" / "munge.key", key);
    ::chmod((dir / "munge" / "munge.key").c_str(), 0600);
  }
  const int port = 20000 + 2 * static_cast<int>(::getpid() % 10000);
  const fs::path conf = dir / "slurm.conf";
  test::write_file(conf, slurm_conf(dir, short_hostname(), port, user_name()));

  Daemons daemons;
  daemons.start(
      {munged, "--foreground", "--force", "--socket=" + (dir / "munge/munge.socket").string(),
       "--key-file=" + (dir / "munge/munge.key").string(),
       "--log-file=" + (dir / "log/munged.log").string(),
       "--pid-file=" + (dir / "munge/munged.pid").string(),
       "--seed-file=" + (dir / "munge/munged.seed").string()},
      dir / "log/munged.out", conf);
  test::wait_until(std::chrono::seconds(5), [&] { return fs::exists(dir / "munge/munge.socket"); });
  daemons.start({slurmctld, "-D"}, dir / "log/slurmctld.out", conf);
  daemons.start({slurmd, "-D"}, dir / "log/slurmd.out", conf);
  const std::string env = "SLURM_CONF='" + conf.string() + "' ";
  const auto node_idle = [&] {
    FILE* pipe = ::popen((env + "sinfo -h -o %T 2>&1").c_str(), "r");
    if (!pipe) return false;
    char buffer[512] = {};
    const std::size_t n = std::fread(buffer, 1, sizeof buffer - 1, pipe);
    ::pclose(pipe);
    return std::string(buffer, n).find("idle") != std::string::npos;
  };
  test::wait_until(std::chrono::seconds(60), node_idle, std::chrono::milliseconds(250));
  ASSERT_TRUE(daemons.all_running())
      << test::read_file(dir / "log/slurmctld.out") << test::read_file(dir / "log/slurmd.out");
  ASSERT_TRUE(node_idle()) << "the node never became idle\n"
                           << test::read_file(dir / "log/slurmctld.log")
                           << test::read_file(dir / "log/slurmd.log");

  const fs::path file = dir / "slurm_study.yaml";
  test::write_file(file,
                   "version: 1\nname: slurm_study\nscene: " + std::string(WIFISLAM_SCENES_DIR) +
                       "/c_hall.yaml\nlevel: radio\naxes:\n  access_points.count: [10, 20]\n"
                       "  access_points.placement: [rooms, random]\n  seed: [1, 2]\n");
  const auto submitted = test::run_wifislam(
      "study slurm " + file.string() + " --tasks 4 -o " + (dir / "job").string() + " --submit", dir,
      {}, env);
  ASSERT_EQ(submitted.exit_code, 0) << submitted.out << submitted.err;
  EXPECT_NE(submitted.out.find("submitted array job"), std::string::npos) << submitted.out;

  const fs::path merged = dir / "job" / "slurm_study.sqlite";
  test::wait_until(
      std::chrono::minutes(5), [&] { return fs::exists(merged); }, std::chrono::milliseconds(500));
  ASSERT_TRUE(fs::exists(merged)) << "no merged database after 5 minutes\n"
                                  << test::read_file(dir / "job/logs/merge.log")
                                  << test::read_file(dir / "job/logs/shard-0.log")
                                  << test::read_file(dir / "log/slurmctld.log");
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(fs::exists(dir / "job" / "shards" / ("shard-" + std::to_string(i) + ".sqlite")));
  }

  StudyRunOptions whole;
  whole.database = dir / "whole.sqlite";
  run_study(load_study_file(file), whole);
  const auto rows = dump_results(merged);
  EXPECT_EQ(rows.size(), 8u);
  EXPECT_EQ(rows, dump_results(whole.database));
  daemons.stop();
  fs::remove_all(dir);
}

}  // namespace
}  // namespace wifislam::study
