// External systems (interop/external_system.hpp) run as a user runs them: the shipped OpenCV RGB-D
// odometry (a real third-party program, python3-opencv) through `compare` beside our front end,
// scored with a finite ATE and no Wi-Fi variant; a broken program as a failed row, never a crash;
// this binary's rgbdslam through the contract scoring exactly as the built-in front end; a system
// that outlives its timeout killed; system files with mistakes refused with a located error; a
// study's `system` axis with a status column.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/cli/shared_dataset.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;
using test::read_file;
using test::write_file;

/// A system that prints a line and exits 3 without writing a trajectory.
constexpr const char* kBrokenSystem = R"yaml(version: 1
name: broken
command: [/usr/bin/python3, -c, "import sys; print('starting'); sys.exit(3)"]
timeout_s: 60
outputs: {trajectory: trajectory.txt}
)yaml";

class ExternalSystemCli : public ::testing::Test {
 protected:
  // One tiny dataset shared by the tests that read one (each writes its own output folder).
  static void SetUpTestSuite() {
    root_ = test::scratch_folder("suite");
    write_file(root_ / "broken.yaml", kBrokenSystem);
    write_file(root_ / "tiny.yaml", test::tiny_wifi_loop_yaml());
    dataset_ = test::shared_tiny_wifi_dataset();
    generated_ = !dataset_.empty();
  }
  void SetUp() override {
    ASSERT_TRUE(generated_);
    scratch_ = test::scratch_folder();
  }
  void TearDown() override { fs::remove_all(scratch_); }

  static fs::path dataset() { return dataset_; }

  /// `slam` of the dataset with the system file `yaml` (written to the scratch folder).
  test::CliResult slam_with_system(const std::string& yaml, const std::string& extra = "") {
    write_file(scratch_ / "system.yaml", yaml);
    return test::run_wifislam("slam " + dataset().string() + " -o " + (scratch_ / "run").string() +
                                  " --frontend external:" + (scratch_ / "system.yaml").string() +
                                  " " + extra,
                              scratch_);
  }

  static inline fs::path root_, dataset_;
  static inline bool generated_ = false;
  fs::path scratch_;
};

/// comparison.csv as rows of fields by column name (the file has no quoted commas here).
std::vector<std::map<std::string, std::string>> csv_rows(const fs::path& file) {
  std::istringstream in(test::read_file(file));
  std::string line;
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream fs_line(line);
    for (std::string f; std::getline(fs_line, f, ',');) fields.push_back(f);
    if (header.empty()) {
      header = fields;
      continue;
    }
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < header.size(); ++i) {
      EXPECT_TRUE(row.emplace(header[i], i < fields.size() ? fields[i] : "").second)
          << "column " << header[i] << " twice in " << file;
    }
    rows.push_back(row);
  }
  return rows;
}

TEST_F(ExternalSystemCli, OpencvOdometryAndABrokenSystemThroughCompare) {
  const test::CliResult r = test::run_wifislam(
      "compare " + (root_ / "tiny.yaml").string() + " --fps 2 -o " + (scratch_ / "cmp").string() +
          " --sweep frontend=rgbdslam,external:opencv_rgbd_odometry,external:" +
          (root_ / "broken.yaml").string(),
      scratch_);
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const auto rows = csv_rows(scratch_ / "cmp" / "comparison.csv");
  int opencv_rows = 0, broken_rows = 0, ours = 0;
  for (const auto& row : rows) {
    const std::string& setting = row.at("setting");
    if (setting == "frontend=rgbdslam") {
      ++ours;
      EXPECT_EQ(row.at("status"), "ok");
      // The Wi-Fi run's own counters are columns although the vanilla run, first, has none.
      ASSERT_TRUE(row.count("counter.wifi_clusters_founded"));
      EXPECT_EQ(row.at("counter.wifi_clusters_founded").empty(), row.at("variant") == "vanilla");
    } else if (setting == "frontend=external:opencv_rgbd_odometry") {
      ++opencv_rows;
      EXPECT_EQ(row.at("variant"), "vanilla");  // it reads no Wi-Fi: no Wi-Fi variant
      EXPECT_EQ(row.at("status"), "ok");
      const double ate_m = std::stod(row.at("ate_rmse_m"));
      EXPECT_TRUE(std::isfinite(ate_m) && ate_m > 0.0 && ate_m < 50.0) << ate_m;
      const nlohmann::json run =
          nlohmann::json::parse(test::read_file(scratch_ / "cmp" / row.at("run_dir") / "run.json"));
      EXPECT_EQ(run.at("frontend"), "external:opencv_rgbd_odometry");
      EXPECT_EQ(run.at("external").at("exit_code"), 0);
      EXPECT_GT(run.at("external").at("cpu_s").get<double>(), 0.0);
    } else {
      ++broken_rows;
      EXPECT_EQ(row.at("status"), "exited 3");
      EXPECT_EQ(row.at("ate_rmse_m"), "");  // no number that could read as a score
      const fs::path run_dir = scratch_ / "cmp" / row.at("run_dir");
      EXPECT_NE(test::read_file(run_dir / "stdout.log").find("starting"), std::string::npos);
      EXPECT_FALSE(fs::exists(run_dir / "trajectory.txt"));
    }
  }
  EXPECT_EQ(ours, 2);
  EXPECT_EQ(opencv_rows, 1);
  EXPECT_EQ(broken_rows, 1);
  // What the comparison records names the folders where they are once it is in place, never
  // the staging folder (cmp.partial) it was written in.
  for (const auto& entry : fs::recursive_directory_iterator(scratch_ / "cmp")) {
    if (!entry.is_regular_file() || entry.path().extension() == ".png") continue;
    EXPECT_EQ(test::read_file(entry.path()).find("cmp.partial"), std::string::npos) << entry.path();
  }
  for (const auto& row : rows) {
    EXPECT_TRUE(fs::is_directory(scratch_ / "cmp" / row.at("dataset_dir")))
        << row.at("dataset_dir");
    if (row.at("status") != "ok") continue;
    const nlohmann::json metrics = nlohmann::json::parse(
        test::read_file(scratch_ / "cmp" / row.at("run_dir") / "eval" / "metrics.json"));
    EXPECT_TRUE(fs::equivalent(metrics.at("run_dir").get<std::string>(),
                               scratch_ / "cmp" / row.at("run_dir")));
    EXPECT_TRUE(fs::equivalent(metrics.at("dataset_dir").get<std::string>(),
                               scratch_ / "cmp" / row.at("dataset_dir")));
  }
  const std::string md = test::read_file(scratch_ / "cmp" / "comparison.md");
  EXPECT_NE(md.find("Runs that failed"), std::string::npos);
  EXPECT_NE(md.find("exited 3"), std::string::npos);
}

/// metrics.json without what differs by design: where the run is, its name and its timing.
nlohmann::json scores(const fs::path& metrics_json) {
  nlohmann::json j = nlohmann::json::parse(test::read_file(metrics_json));
  for (const char* key : {"run_dir", "frontend", "timing"}) j.erase(key);
  return j;
}

TEST_F(ExternalSystemCli, OwnBinaryThroughTheContractScoresAsTheBuiltInFrontEnd) {
  const std::string input = dataset().string();
  for (const auto& [run, frontend] :
       {std::pair{"builtin", "rgbdslam"}, std::pair{"external", "external:wifislam_rgbdslam"}}) {
    const fs::path dir = scratch_ / run;
    const test::CliResult s = test::run_wifislam(
        "slam " + input + " --wifi --frontend " + frontend + " -o " + dir.string(), scratch_);
    ASSERT_EQ(s.exit_code, 0) << s.err;
    const test::CliResult e = test::run_wifislam(
        "eval " + dir.string() + " --gt " + input + " -o " + (dir / "eval").string(), scratch_);
    ASSERT_EQ(e.exit_code, 0) << e.err;
  }
  EXPECT_TRUE(fs::exists(scratch_ / "external" / "loop_closures.csv"));
  EXPECT_TRUE(fs::exists(scratch_ / "external" / "wifi_clusters.csv"));
  const nlohmann::json builtin = scores(scratch_ / "builtin" / "eval" / "metrics.json");
  const nlohmann::json external = scores(scratch_ / "external" / "eval" / "metrics.json");
  EXPECT_EQ(builtin.dump(1), external.dump(1));
  EXPECT_TRUE(builtin.at("loop_closures").is_object());
}

/// A stand-in for rtabmap-rgbd_dataset (RTAB-Map is not in Debian): it checks the export has the
/// calibration file, writes the export's ground truth as rtabmap_poses.txt (TUM lines, as
/// graph::exportPoses format 1 does), and a database whose Link table holds one accepted loop
/// closure between two graph nodes, one to a node of an earlier map (after an odometry reset: not
/// in the exported poses) and one neighbour link (type 0).
constexpr const char* kRtabmapStandIn = R"sh(#!/bin/sh
set -eu
out="$2"; export_dir="$3"
test -f "$export_dir/rtabmap_calib.yaml"
test -d "$export_dir/rgb_sync"
grep -v '^#' "$export_dir/groundtruth.txt" > "$out/rtabmap_poses.txt"
first=$(head -n 1 "$out/rtabmap_poses.txt" | cut -d ' ' -f 1)
last=$(tail -n 1 "$out/rtabmap_poses.txt" | cut -d ' ' -f 1)
sqlite3 "$out/rtabmap.db" "CREATE TABLE Node(id INTEGER, stamp REAL);
  CREATE TABLE Link(from_id INTEGER, to_id INTEGER, type INTEGER);
  INSERT INTO Node VALUES (1, $first), (2, $last), (3, 1000.5);
  INSERT INTO Link VALUES (2, 1, 1), (3, 1, 1), (2, 1, 0);"
)sh";

TEST_F(ExternalSystemCli, ShippedRtabmapWrapperKeepsOnlyClosuresBetweenNodesOfTheExportedGraph) {
  const fs::path tool = scratch_ / "rtabmap-rgbd_dataset";
  write_file(tool, kRtabmapStandIn);
  fs::permissions(tool, fs::perms::owner_all);
  const fs::path run = scratch_ / "run";
  const test::CliResult r = test::run_wifislam(
      "slam " + dataset().string() + " --frontend external:rtabmap -o " + run.string(), scratch_,
      {}, "RTABMAP_DATASET_TOOL='" + tool.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream lines(test::read_file(run / "loop_closures.csv"));
  std::string header, closure, more;
  std::getline(lines, header);
  std::getline(lines, closure);
  EXPECT_FALSE(std::getline(lines, more)) << "more than the one closure in the graph: " << more;
  EXPECT_NE(header.find("from_time"), std::string::npos) << header;
  const test::CliResult e = test::run_wifislam(
      "eval " + run.string() + " --gt " + dataset().string() + " -o " + (run / "eval").string(),
      scratch_);
  ASSERT_EQ(e.exit_code, 0) << e.err;
  const nlohmann::json metrics =
      nlohmann::json::parse(test::read_file(run / "eval" / "metrics.json"));
  EXPECT_LT(metrics.at("trajectory").at("ate_rmse_m").get<double>(), 1e-3) << metrics.dump(1);
  const nlohmann::json& closures = metrics.at("loop_closures");
  EXPECT_TRUE(closures.at("available").get<bool>()) << closures.dump(1);
  EXPECT_EQ(closures.at("loop_closure_csv_rows").get<int>(), 1) << closures.dump(1);
}

TEST_F(ExternalSystemCli, ATimedOutSystemIsKilledAndSaysSo) {
  const auto start = std::chrono::steady_clock::now();
  const test::CliResult r = slam_with_system(R"(version: 1
name: sleeper
command: /bin/sleep 60
timeout_s: 1
outputs: {trajectory: t.txt}
)");
  const double took_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.exit_code, 5) << r.err;
  EXPECT_LT(took_s, 20.0);
  EXPECT_NE(r.err.find("timed out"), std::string::npos) << r.err;
  const nlohmann::json run = nlohmann::json::parse(test::read_file(scratch_ / "run" / "run.json"));
  EXPECT_NE(run.at("external").at("status").get<std::string>().find("timed out"),
            std::string::npos);
}

TEST_F(ExternalSystemCli, SystemFileMistakesAreLocatedBadInput) {
  struct Case {
    std::string yaml, what;
  };
  const std::string head = "version: 1\nname: s\n";
  const std::vector<Case> cases = {
      {head + "command: [/bin/true]\noutputs: {trajectory: t.txt}\ntimeout: 3\n", "timeout"},
      {head + "command: [/bin/true, \"{datset}\"]\noutputs: {trajectory: t.txt}\n", "{datset}"},
      {head + "command: [/bin/true]\noutputs: {trajectory: ../t.txt}\n", "outputs.trajectory"},
      {head + "command: [/bin/true]\noutputs: {keyframes: k.txt}\n", "outputs.trajectory"},
      {head + "command: []\noutputs: {trajectory: t.txt}\n", "command"},
      {head + "command: [/bin/true, \"{rgbd_export}\"]\noutputs: {trajectory: t.txt}\n", "export"},
      {head + "command: [/bin/true]\noutputs: {trajectory: t.txt, graph: g.json}\n",
       "outputs.graph"},
  };
  for (const Case& c : cases) {
    const test::CliResult r = slam_with_system(c.yaml);
    test::expect_located_bad_input(r, (scratch_ / "system.yaml").string() + ":", c.what);
    EXPECT_FALSE(fs::exists(scratch_ / "run")) << c.yaml;
  }
}

TEST_F(ExternalSystemCli, WifiOfASystemThatReadsNoneIsRefused) {
  const test::CliResult r = test::run_wifislam(
      "slam " + dataset().string() + " --wifi --frontend external:opencv_rgbd_odometry -o " +
          (scratch_ / "run").string(),
      scratch_);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("Wi-Fi"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(scratch_ / "run"));
}

TEST_F(ExternalSystemCli, StudySystemAxisGivesAStatusPerRow) {
  write_file(scratch_ / "study.yaml",
             "version: 1\nname: systems\nscene: " + (root_ / "tiny.yaml").string() +
                 "\nlevel: slam\naxes:\n  system: [rgbdslam, " + (root_ / "broken.yaml").string() +
                 "]\nslam: {fps: 2, max_frames: 30}\n");
  const test::CliResult r = test::run_wifislam(
      "study run " + (scratch_ / "study.yaml").string() + " -o " + (scratch_ / "s.sqlite").string(),
      scratch_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string query = "sqlite3 " + (scratch_ / "s.sqlite").string() +
                            " \"SELECT variant, status, ate_rmse_m IS NULL FROM results ORDER BY "
                            "case_index, variant\" > " +
                            (scratch_ / "rows.txt").string();
  ASSERT_EQ(std::system(query.c_str()), 0);
  EXPECT_EQ(test::read_file(scratch_ / "rows.txt"),
            "vanilla|ok|0\nwifi|ok|0\nvanilla|exited 3|1\n");
  const test::CliResult p = test::run_wifislam(
      "study plot " + (scratch_ / "s.sqlite").string() + " -o " + (scratch_ / "plots").string(),
      scratch_);
  EXPECT_EQ(p.exit_code, 0) << p.err;
  EXPECT_TRUE(fs::exists(scratch_ / "plots" / "ate_rmse_m.png"));
}

}  // namespace
}  // namespace wifislam
