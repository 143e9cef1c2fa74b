// `wifislam eval` end to end: a real small run (generate -> slam -> eval through the command
// line), a Wi-Fi cluster plot from a hand-written wifi_clusters.csv, and bad input.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/eval/ladder_dataset.hpp"

namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  return fs::temp_directory_path() /
         ("wifislam_eval_cli_" + name + "_" + std::to_string(::getpid()));
}

struct Result {
  int exit_code = -1;
  std::string out, err;
};

Result wifislam(const std::string& args, const fs::path& dir) {
  const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string command =
      std::string(WIFISLAM_BINARY) + " " + args + " >" + out.string() + " 2>" + err.string();
  const int status = std::system(command.c_str());
  Result r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::stringstream o, e;
  o << std::ifstream(out).rdbuf();
  e << std::ifstream(err).rdbuf();
  r.out = o.str();
  r.err = e.str();
  return r;
}

bool is_png(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  char sig[8] = {};
  in.read(sig, 8);
  return in && std::string(sig + 1, 3) == "PNG" && fs::file_size(p) > 2000;
}

bool is_svg(const fs::path& p) {
  std::stringstream s;
  s << std::ifstream(p).rdbuf();
  return s.str().find("<svg") != std::string::npos && fs::file_size(p) > 2000;
}

std::vector<std::string> csv_line_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.push_back(field);
      field.clear();
    } else {
      field += c;
    }
  }
  fields.push_back(field);
  return fields;
}

const char* kSmallLoop = R"(version: 1
name: eval_small_loop
description: Small square loop with unique wall looks, for the eval command test.
seed: 91
building: {wall_height_m: 2.8, wall_thickness_m: 0.15}
nodes:
  - {id: A, position_m: [0, 0]}
  - {id: B, position_m: [7, 0]}
  - {id: C, position_m: [7, 5]}
  - {id: D, position_m: [0, 5]}
corridors:
  - {id: south, from: A, to: B, width_m: 2.0}
  - {id: east, from: B, to: C, width_m: 2.0}
  - {id: north, from: C, to: D, width_m: 2.0}
  - {id: west, from: D, to: A, width_m: 2.0}
appearance:
  aliasing: 0.0
  posters_per_10m: 4.0
access_points: {placement: random, count: 8}
route:
  nodes: [A, B, C, D, A, B]
  speed_mps: 0.5
  pause: {spacing_m: [3.0, 4.0], duration_s: 1.0}
radio: {environment: office}
)";

TEST(EvalCommand, RealSmallRunWritesReportMetricsAndPlots) {
  const fs::path dir = scratch("real");
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "small.yaml") << kSmallLoop;
  const fs::path ds = dir / "ds", run = dir / "run";
  ASSERT_EQ(
      wifislam("generate " + (dir / "small.yaml").string() + " --fps 2 -q -o " + ds.string(), dir)
          .exit_code,
      0);
  const Result slam = wifislam("slam " + ds.string() + " -o " + run.string(), dir);
  ASSERT_EQ(slam.exit_code, 0) << slam.err;
  const Result r = wifislam(
      "eval " + run.string() + " --gt " + ds.string() + " --set revisit_min_path_m=8", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("ATE RMSE"), std::string::npos) << r.out;
  const fs::path out = run / "eval";
  for (const char* f : {"report.md", "metrics.json", "metrics.csv"}) {
    EXPECT_TRUE(fs::is_regular_file(out / f)) << f;
  }
  for (const char* f : {"trajectory", "ate_along_path"}) {
    EXPECT_TRUE(is_png(out / (std::string(f) + ".png"))) << f;
    EXPECT_TRUE(is_svg(out / (std::string(f) + ".svg"))) << f;
  }
  EXPECT_FALSE(fs::exists(out / "wifi_clusters.png"));  // not a Wi-Fi run
  EXPECT_FALSE(fs::exists(run / "eval.partial"));

  const nlohmann::json m = nlohmann::json::parse(std::ifstream(out / "metrics.json"));
  EXPECT_EQ(m["thresholds"]["revisit_min_path_m"], 8.0);  // --set reaches the outputs
  EXPECT_EQ(m["thresholds"]["overlap_min_fraction"], 0.2);
  const double rmse = m["trajectory"]["ate_rmse_m"];
  EXPECT_GT(rmse, 0.0);
  EXPECT_GT(m["trajectory"]["frames_associated"].get<int>(), 100);
  EXPECT_EQ(m["loop_closures"]["overlap_used_depth"], true);
  // The run's own loop-closure count agrees with what eval read.
  const nlohmann::json timing = nlohmann::json::parse(std::ifstream(run / "timing.json"));
  if (timing["counters"].contains("loop_closures")) {
    EXPECT_EQ(m["loop_closures"]["detected"], timing["counters"]["loop_closures"]);
  }

  std::ifstream csv(out / "metrics.csv");
  std::string header, row, extra;
  std::getline(csv, header);
  std::getline(csv, row);
  EXPECT_FALSE(std::getline(csv, extra));
  const auto names = csv_line_fields(header), values = csv_line_fields(row);
  ASSERT_EQ(names.size(), values.size());
  const auto at = std::find(names.begin(), names.end(), "ate_rmse_m") - names.begin();
  ASSERT_LT(static_cast<std::size_t>(at), names.size());
  EXPECT_NEAR(std::stod(values[static_cast<std::size_t>(at)]), rmse, 1e-12 * rmse);
  EXPECT_NE(std::find(names.begin(), names.end(), "threshold.loop_max_rotation_error_deg"),
            names.end());

  std::stringstream report;
  report << std::ifstream(out / "report.md").rdbuf();
  EXPECT_NE(report.str().find("## Thresholds"), std::string::npos);
  EXPECT_NE(report.str().find("overlap_min_fraction"), std::string::npos);
  fs::remove_all(dir);
}

TEST(EvalCommand, WifiRunGetsClusterPlot) {
  const fs::path dir = scratch("wifi");
  const wifislam::test::LadderRun run = wifislam::test::build_ladder_run(dir, false);
  std::ofstream(run.run_dir / "run.json") << R"({"frontend": "rgbdslam", "wifi": true})";
  std::ofstream(run.run_dir / "wifi_clusters.csv")
      << "cluster_id,founder_keyframe,keyframes,representative_signature\n"
         "0,0,0 1 2 3 4,02:1a:11:00:00:30=-61.5;02:1a:11:00:00:40=-70\n"
         "1,5,5 6 7 8 9 10,02:1a:11:00:00:50=-55\n";
  const Result r = wifislam("eval " + run.run_dir.string() + " --gt " + run.dataset_dir.string() +
                                " -o " + (dir / "out").string(),
                            dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(is_png(dir / "out" / "wifi_clusters.png"));
  EXPECT_TRUE(is_svg(dir / "out" / "wifi_clusters.svg"));
  EXPECT_NE(r.out.find("geometric bound only"), std::string::npos) << r.out;
  const nlohmann::json m = nlohmann::json::parse(std::ifstream(dir / "out" / "metrics.json"));
  EXPECT_EQ(m["wifi_clusters"], 2);
  EXPECT_EQ(m["wifi_run"], true);
  fs::remove_all(dir);
}

// Whether a run used Wi-Fi is what its run.json says, not which files lie in the folder.
TEST(EvalCommand, WifiRunIsWhatRunJsonSays) {
  const fs::path dir = scratch("wifi_flag");
  const wifislam::test::LadderRun run = wifislam::test::build_ladder_run(dir, false);
  // A stray clusters file in a vanilla run is not read.
  std::ofstream(run.run_dir / "wifi_clusters.csv") << "not,a,clusters,file\n";
  Result r = wifislam("eval " + run.run_dir.string() + " --gt " + run.dataset_dir.string() +
                          " --no-plots -o " + (dir / "vanilla").string(),
                      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json m = nlohmann::json::parse(std::ifstream(dir / "vanilla" / "metrics.json"));
  EXPECT_EQ(m["wifi_run"], false);
  // A Wi-Fi run without its clusters file is an error naming the file.
  fs::remove(run.run_dir / "wifi_clusters.csv");
  std::ofstream(run.run_dir / "run.json") << R"({"frontend": "rgbdslam", "wifi": true})";
  r = wifislam("eval " + run.run_dir.string() + " --gt " + run.dataset_dir.string() + " -o " +
                   (dir / "wifi").string(),
               dir);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("wifi_clusters.csv"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "wifi"));
  // A version-1 run folder named its Wi-Fi runs "<frontend>+wifi" and had no "wifi" key.
  std::ofstream(run.run_dir / "wifi_clusters.csv")
      << "cluster_id,founder_keyframe,keyframes,representative_signature\n"
         "0,0,0 1 2,02:1a:11:00:00:30=-61.5\n";
  std::ofstream(run.run_dir / "run.json") << R"({"frontend": "rgbdslam+wifi"})";
  r = wifislam("eval " + run.run_dir.string() + " --gt " + run.dataset_dir.string() +
                   " --no-plots -o " + (dir / "v1").string(),
               dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json v1 = nlohmann::json::parse(std::ifstream(dir / "v1" / "metrics.json"));
  EXPECT_EQ(v1["wifi_run"], true);
  EXPECT_EQ(v1["frontend"], "rgbdslam");
  // A run folder from a newer format is refused, naming the key.
  std::ofstream(run.run_dir / "run.json") << R"({"format_version": 99, "frontend": "rgbdslam"})";
  r = wifislam("eval " + run.run_dir.string() + " --gt " + run.dataset_dir.string() + " -o " +
                   (dir / "v99").string(),
               dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("format_version"), std::string::npos) << r.err;
  // A wrongly typed flag is located.
  std::ofstream(run.run_dir / "run.json") << R"({"frontend": "rgbdslam", "wifi": "yes"})";
  r = wifislam("eval " + run.run_dir.string() + " --gt " + run.dataset_dir.string() + " -o " +
                   (dir / "typed").string(),
               dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("run.json"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("wifi"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(EvalCommand, BadInputFailsWithoutOutput) {
  const fs::path dir = scratch("bad");
  const wifislam::test::LadderRun run = wifislam::test::build_ladder_run(dir, false);
  const fs::path out = dir / "out";
  const std::string args =
      "eval " + run.run_dir.string() + " --gt " + run.dataset_dir.string() + " -o " + out.string();

  // NaN in the estimated trajectory: the file and line are named.
  const fs::path trajectory = run.run_dir / "trajectory.txt";
  fs::copy_file(trajectory, dir / "trajectory.good");
  { std::ofstream(trajectory, std::ios::app) << "999.000000 nan 0 0 0 0 0 1\n"; }
  Result r = wifislam(args, dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("trajectory.txt:"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
  fs::copy_file(dir / "trajectory.good", trajectory, fs::copy_options::overwrite_existing);

  // Missing ground truth.
  fs::rename(run.dataset_dir / "groundtruth.txt", dir / "groundtruth.txt");
  r = wifislam(args, dir);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("groundtruth.txt"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  fs::rename(dir / "groundtruth.txt", run.dataset_dir / "groundtruth.txt");

  // Unknown threshold.
  r = wifislam(args + " --set overlap_fraction=0.3", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("overlap_fraction"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));

  // And the repaired folder evaluates.
  r = wifislam(args, dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "metrics.json"));
  fs::remove_all(dir);
}

}  // namespace
