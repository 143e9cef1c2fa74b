// `wifislam eval` end to end: a real small run (generate -> slam -> eval through the command
// line), a Wi-Fi cluster plot from a hand-written wifi_clusters.csv, and bad input.

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/eval/ladder_dataset.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/scratch_folder.hpp"

namespace {

namespace fs = std::filesystem;
using wifislam::test::CliResult;
using wifislam::test::run_wifislam;

fs::path scratch(const std::string& name) { return wifislam::test::scratch_folder(name); }

std::string fmt_stamp(double t) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6f", t);
  return buf;
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

const std::string kSmallLoop = wifislam::test::square_loop_yaml(
    {.name = "eval_small_loop",
     .description = "Small square loop with unique wall looks, for the eval command test.",
     .route = "A, B, C, D, A, B"});

/// A fresh `dir` with the small loop generated at 2 fps (dir/ds) and run by `slam` (dir/run).
/// False when either command failed.
bool generate_and_run(const fs::path& dir) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "small.yaml") << kSmallLoop;
  const std::string ds = (dir / "ds").string();
  return run_wifislam("generate " + (dir / "small.yaml").string() + " --fps 2 -q -o " + ds, dir)
                 .exit_code == 0 &&
         run_wifislam("slam " + ds + " -o " + (dir / "run").string(), dir).exit_code == 0;
}

TEST(EvalCommand, RealSmallRunWritesReportMetricsAndPlots) {
  const fs::path dir = scratch("real");
  ASSERT_TRUE(generate_and_run(dir));
  const fs::path ds = dir / "ds", run = dir / "run";
  const CliResult r = run_wifislam(
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
  // The run's own loop-closure count agrees with the loop_closures.csv rows eval read.
  const nlohmann::json timing = nlohmann::json::parse(std::ifstream(run / "timing.json"));
  if (timing["counters"].contains("loop_closures")) {
    EXPECT_EQ(m["loop_closures"]["loop_closure_csv_rows"], timing["counters"]["loop_closures"]);
  }
  EXPECT_EQ(m["loop_closures"]["source"], "graph.json");
  EXPECT_EQ(m["loop_closures"]["online"]["scored"].get<int>(),
            m["loop_closures"]["online"]["correct"].get<int>() +
                m["loop_closures"]["online"]["right_place_imprecise"].get<int>() +
                m["loop_closures"]["online"]["wrong_place"].get<int>());

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
  for (const char* key : {"online_correct", "online_right_place_imprecise", "online_wrong_place",
                          "online_far_wrong_place", "online_false_positive_pct",
                          "online_false_negatives", "pruned_correct", "pruned_wrong_place",
                          "pruned_false_positive_pct", "pruned_false_negatives"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), key), names.end()) << key;
  }

  std::stringstream report;
  report << std::ifstream(out / "report.md").rdbuf();
  EXPECT_NE(report.str().find("## Thresholds"), std::string::npos);
  EXPECT_NE(report.str().find("overlap_min_fraction"), std::string::npos);

  // The ground truth of another recording (seed 92: the same frame times, other poses) is
  // refused, naming both recordings, and nothing is written; the trajectory file on its own
  // may still be scored against it.
  const fs::path other = dir / "other_seed";
  const CliResult generated =
      run_wifislam("generate " + (dir / "small.yaml").string() +
                       " --fps 2 --seed 92 --no-images -q -o " + other.string(),
                   dir);
  ASSERT_EQ(generated.exit_code, 0) << generated.err;
  const CliResult refused = run_wifislam(
      "eval " + run.string() + " --gt " + other.string() + " -o " + (dir / "refused").string(),
      dir);
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("made from the recording of scene eval_small_loop, seed 91, 2 fps"),
            std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("holds the recording of scene eval_small_loop, seed 92, 2 fps"),
            std::string::npos)
      << refused.err;
  EXPECT_FALSE(fs::exists(dir / "refused"));
  const CliResult bare =
      run_wifislam("eval " + (run / "trajectory.txt").string() + " --gt " + other.string() +
                       " --no-plots -o " + (dir / "bare").string(),
                   dir);
  EXPECT_EQ(bare.exit_code, 0) << bare.err;
  fs::remove_all(dir);
}

TEST(EvalCommand, RequirementsMakeARegressionTestWithItsOwnExitCode) {
  const fs::path dir = scratch("require");
  ASSERT_TRUE(generate_and_run(dir));
  const fs::path ds = dir / "ds", run = dir / "run";
  const std::string eval = "eval " + run.string() + " --gt " + ds.string() + " --no-plots -o ";
  const CliResult plain = run_wifislam(eval + (dir / "plain").string(), dir);
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  std::ifstream metrics_file(dir / "plain" / "metrics.json");
  const nlohmann::json metrics = nlohmann::json::parse(metrics_file);
  const double ate = metrics.at("trajectory").at("ate_rmse_m").get<double>();
  ASSERT_GT(ate, 0.0);

  // Met: exit 0 and says so.
  const CliResult met = run_wifislam(eval + (dir / "met").string() +
                                         " --require 'ate_rmse_m<=" + std::to_string(ate * 2) +
                                         "' --require 'frames_associated>=10'",
                                     dir);
  EXPECT_EQ(met.exit_code, 0) << met.err;
  EXPECT_NE(met.out.find("requirement        met: ate_rmse_m = "), std::string::npos) << met.out;
  // Not met: exit 6, the outputs written all the same, the miss named with its size.
  const CliResult missed = run_wifislam(
      eval + (dir / "missed").string() + " --require 'ate_rmse_m<=" + std::to_string(ate / 2) + "'",
      dir);
  EXPECT_EQ(missed.exit_code, 6) << missed.err;
  EXPECT_NE(missed.out.find("NOT met: ate_rmse_m = "), std::string::npos) << missed.out;
  EXPECT_NE(missed.out.find("above"), std::string::npos) << missed.out;
  EXPECT_NE(missed.err.find("1 of 1 requirements not met"), std::string::npos) << missed.err;
  EXPECT_TRUE(fs::exists(dir / "missed" / "metrics.json"));
  // A bare trajectory has no loop closures: a requirement on them is not met.
  const CliResult bare = run_wifislam(
      "eval " + (run / "trajectory.txt").string() + " --gt " + ds.string() + " --no-plots -o " +
          (dir / "bare").string() + " --require 'online_wrong_place==0'",
      dir);
  EXPECT_EQ(bare.exit_code, 6) << bare.err;
  EXPECT_NE(bare.out.find("not available"), std::string::npos) << bare.out;
  // Malformed or unknown: exit 2 before anything is written.
  for (const char* bad : {"ate_rmse_m<=abc", "ate_rms_m<=1", "ate_rmse_m"}) {
    const fs::path out = dir / "bad";
    const CliResult r = run_wifislam(eval + out.string() + " --require '" + bad + "'", dir);
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.err;
    EXPECT_NE(r.err.find(bad), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << bad;
  }
  // A ground truth edited after generation is refused against manifest.json, and scored with
  // --no-verify (as `slam --no-verify` reads such a dataset).
  std::ofstream(ds / "groundtruth.txt", std::ios::app) << "# edited\n";
  const CliResult edited = run_wifislam(eval + (dir / "edited").string(), dir);
  EXPECT_EQ(edited.exit_code, 2) << edited.err;
  EXPECT_NE(edited.err.find("manifest mismatch"), std::string::npos) << edited.err;
  EXPECT_FALSE(fs::exists(dir / "edited"));
  const CliResult unverified = run_wifislam(eval + (dir / "edited").string() + " --no-verify", dir);
  EXPECT_EQ(unverified.exit_code, 0) << unverified.err;
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
  const CliResult r = run_wifislam("eval " + run.run_dir.string() + " --gt " +
                                       run.dataset_dir.string() + " -o " + (dir / "out").string(),
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
  CliResult r = run_wifislam("eval " + run.run_dir.string() + " --gt " + run.dataset_dir.string() +
                                 " --no-plots -o " + (dir / "vanilla").string(),
                             dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json m = nlohmann::json::parse(std::ifstream(dir / "vanilla" / "metrics.json"));
  EXPECT_EQ(m["wifi_run"], false);
  // A Wi-Fi run without its clusters file is an error naming the file.
  fs::remove(run.run_dir / "wifi_clusters.csv");
  std::ofstream(run.run_dir / "run.json") << R"({"frontend": "rgbdslam", "wifi": true})";
  r = run_wifislam("eval " + run.run_dir.string() + " --gt " + run.dataset_dir.string() + " -o " +
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
  r = run_wifislam("eval " + run.run_dir.string() + " --gt " + run.dataset_dir.string() +
                       " --no-plots -o " + (dir / "v1").string(),
                   dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json v1 = nlohmann::json::parse(std::ifstream(dir / "v1" / "metrics.json"));
  EXPECT_EQ(v1["wifi_run"], true);
  EXPECT_EQ(v1["frontend"], "rgbdslam");
  // A run folder from a newer format is refused, naming the key.
  std::ofstream(run.run_dir / "run.json") << R"({"format_version": 99, "frontend": "rgbdslam"})";
  r = run_wifislam("eval " + run.run_dir.string() + " --gt " + run.dataset_dir.string() + " -o " +
                       (dir / "v99").string(),
                   dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("format_version"), std::string::npos) << r.err;
  // A wrongly typed flag is located.
  std::ofstream(run.run_dir / "run.json") << R"({"frontend": "rgbdslam", "wifi": "yes"})";
  r = run_wifislam("eval " + run.run_dir.string() + " --gt " + run.dataset_dir.string() + " -o " +
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
  CliResult r = run_wifislam(args, dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("trajectory.txt:"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
  fs::copy_file(dir / "trajectory.good", trajectory, fs::copy_options::overwrite_existing);

  // Missing ground truth.
  fs::rename(run.dataset_dir / "groundtruth.txt", dir / "groundtruth.txt");
  r = run_wifislam(args, dir);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("groundtruth.txt"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  fs::rename(dir / "groundtruth.txt", run.dataset_dir / "groundtruth.txt");

  // Unknown threshold.
  r = run_wifislam(args + " --set overlap_fraction=0.3", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("overlap_fraction"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));

  // Unknown alignment.
  r = run_wifislam(args + " --align similarity", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--align"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));

  // A graph.json edge without its relative pose: the file and the key are named.
  std::ofstream(run.run_dir / "graph.json")
      << R"({"edges": [{"from": 0, "to": 1, "type": "odometry", "from_to": {"t": [0, 0, 0],
         "q_xyzw": [0, 0, 0, 1]}}, {"from": 0, "to": 40, "type": "loop"}]})";
  r = run_wifislam(args, dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("graph.json"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("edges[1].from_to"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
  fs::remove(run.run_dir / "graph.json");

  // And the repaired folder evaluates.
  r = run_wifislam(args, dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "metrics.json"));
  fs::remove_all(dir);
}

// Another system's trajectory: a bare TUM file (or a folder holding only trajectory.txt) is
// scored on its trajectory alone, and the outputs say loop closures and timing were not there.
TEST(EvalCommand, BareTrajectoryFileGetsTrajectoryTablesOnly) {
  const fs::path dir = scratch("bare");
  const wifislam::test::LadderRun run = wifislam::test::build_ladder_run(dir, false);
  const fs::path file = dir / "CameraTrajectory.txt";
  fs::copy_file(run.run_dir / "trajectory.txt", file);
  CliResult r = run_wifislam("eval " + file.string() + " --gt " + run.dataset_dir.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("not available"), std::string::npos) << r.out;
  const fs::path out = dir / "CameraTrajectory_eval";
  EXPECT_TRUE(is_png(out / "trajectory.png"));
  EXPECT_TRUE(is_png(out / "ate_along_path.png"));
  const nlohmann::json m = nlohmann::json::parse(std::ifstream(out / "metrics.json"));
  EXPECT_LT(m["trajectory"]["ate_rmse_m"].get<double>(), 1e-6);  // rigidly moved ground truth
  EXPECT_EQ(m["loop_closures"]["available"], false);
  EXPECT_EQ(m["timing"]["available"], false);
  EXPECT_FALSE(m["loop_closures"].contains("online"));
  std::stringstream report, csv;
  report << std::ifstream(out / "report.md").rdbuf();
  csv << std::ifstream(out / "metrics.csv").rdbuf();
  EXPECT_NE(report.str().find("Loop closures not available"), std::string::npos) << report.str();
  EXPECT_NE(report.str().find("Timing not available"), std::string::npos);
  EXPECT_NE(report.str().find("| ATE | RMSE"), std::string::npos);
  EXPECT_EQ(csv.str().find("online_wrong_place"), std::string::npos);
  EXPECT_NE(csv.str().find("loop_closures_available"), std::string::npos);

  // A folder with only trajectory.txt.
  const fs::path only = dir / "only_trajectory";
  fs::create_directories(only);
  fs::copy_file(file, only / "trajectory.txt");
  r = run_wifislam("eval " + only.string() + " --gt " + run.dataset_dir.string() + " --no-plots",
                   dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json m2 = nlohmann::json::parse(std::ifstream(only / "eval" / "metrics.json"));
  EXPECT_EQ(m2["loop_closures"]["available"], false);
  EXPECT_NE(m2["loop_closures"]["note"].get<std::string>().find("keyframes.txt"),
            std::string::npos);
  fs::remove_all(dir);
}

TEST(EvalCommand, AlignNoneAndTimeOffset) {
  const fs::path dir = scratch("align");
  const wifislam::test::LadderRun run = wifislam::test::build_ladder_run(dir, false);
  const fs::path file = run.run_dir / "trajectory.txt";
  auto ate = [&](const std::string& options, const std::string& name) {
    const CliResult r = run_wifislam("eval " + file.string() + " --gt " + run.dataset_dir.string() +
                                         " --no-plots -o " + (dir / name).string() + " " + options,
                                     dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json m = nlohmann::json::parse(std::ifstream(dir / name / "metrics.json"));
    EXPECT_EQ(m["trajectory"]["alignment"]["mode"],
              options.find("none") != std::string::npos ? "none" : "se3");
    return m["trajectory"]["ate_rmse_m"].get<double>();
  };
  // The estimate is the ground truth in another frame (5.8 m and 23 deg away): SE(3) alignment
  // removes that, none keeps it.
  EXPECT_LT(ate("", "se3"), 1e-6);
  EXPECT_LT(ate("--align se3", "se3b"), 1e-6);
  EXPECT_GT(ate("--align none", "none"), 3.0);

  // Stamps 30 ms late: nothing pairs within 20 ms (exit 2, no output) until the offset undoes it.
  std::ifstream in(file);
  std::ofstream late(dir / "late.txt");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double t = 0;
    fields >> t;
    std::string rest;
    std::getline(fields, rest);
    late << fmt_stamp(t + 0.03) << rest << "\n";
  }
  late.close();
  CliResult r = run_wifislam("eval " + (dir / "late.txt").string() + " --gt " +
                                 run.dataset_dir.string() + " -o " + (dir / "late_out").string(),
                             dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("share a timestamp"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "late_out"));
  r = run_wifislam("eval " + (dir / "late.txt").string() + " --gt " + run.dataset_dir.string() +
                       " --time-offset -0.03 --no-plots -o " + (dir / "late_out").string(),
                   dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json m = nlohmann::json::parse(std::ifstream(dir / "late_out" / "metrics.json"));
  EXPECT_LT(m["trajectory"]["ate_rmse_m"].get<double>(), 1e-6);
  EXPECT_EQ(m["thresholds"]["time_offset_s"], -0.03);
  // The offset given twice (flag and --set): the later one won silently, in either order.
  r = run_wifislam("eval " + (dir / "late.txt").string() + " --gt " + run.dataset_dir.string() +
                       " --time-offset -0.03 --set time_offset_s=0.5 -o " +
                       (dir / "twice").string(),
                   dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("conflicts with --time-offset"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "twice"));
  // So did the alignment (--set align= won over --align and --scale), and `--align ''` was the
  // default.
  for (const std::string& flags :
       {std::string("--align none --set align=sim3"), std::string("--set align=se3 --scale"),
        std::string("--align ''")}) {
    r = run_wifislam("eval " + (dir / "late.txt").string() + " --gt " + run.dataset_dir.string() +
                         " " + flags + " -o " + (dir / "twice").string(),
                     dir);
    EXPECT_EQ(r.exit_code, 2) << flags << ": " << r.err;
    EXPECT_NE(r.err.find(flags.find("--set") != std::string::npos ? "conflicts with"
                                                                  : "expected none, se3 or sim3"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir / "twice"));
  }
  fs::remove_all(dir);
}

}  // namespace
