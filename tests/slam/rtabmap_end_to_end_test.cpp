// `wifislam slam --frontend rtabmap [--wifi]` through the command line on a small generated loop:
// the run folder is complete (rtabmap_memory.csv one row per node, memory totals in run.json) and
// `wifislam eval` accepts it.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/run_format.hpp"
#include "slam/frontend/rtabmap/rtabmap_memory_csv.hpp"
#include "tests/cli/shared_dataset.hpp"
#include "tests/slam/slam_test_scene.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;

class RtabmapEndToEnd : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = test::scratch_folder();
    dataset_ = test::shared_dataset(test::small_loop_with_wifi_scene_yaml(), "--fps 2");
    generated_ = !dataset_.empty();
  }

  void run_and_check(bool wifi) {
    ASSERT_TRUE(generated_) << "the shared dataset was not generated";
    const fs::path run = dir_ / (wifi ? "run_wifi" : "run_vanilla");
    const test::CliResult slam = test::run_wifislam(
        "slam " + dataset_.string() + " --frontend rtabmap" + (wifi ? " --wifi" : "") +
            " --set max_keypoints=500 -o " + run.string(),
        dir_);
    ASSERT_EQ(slam.exit_code, 0) << slam.err;
    namespace rf = run_folder;
    for (const char* f :
         {rf::kTrajectory, rf::kKeyframes, rf::kGraph, rf::kLoopClosures, rf::kTiming, rf::kRun,
          slam::frontend::rtabmap::rtabmap_memory_csv::kFileName}) {
      EXPECT_TRUE(fs::is_regular_file(run / f)) << f;
    }
    EXPECT_EQ(fs::exists(run / rf::kWifiClusters), wifi);

    const nlohmann::json j = check_run_json(run, wifi);
    if (HasFatalFailure()) return;
    const int keyframes = j.at("keyframes");
    check_node_schedule(run, j, keyframes);
    if (HasFatalFailure()) return;
    check_memory_csv(run, j, keyframes);
    if (HasFatalFailure()) return;
    check_eval(run, wifi, j, keyframes);
  }

  /// run.json names the front end and the Wi-Fi switch, and its memory adds up.
  static nlohmann::json check_run_json(const fs::path& run, bool wifi) {
    namespace rf = run_folder;
    const nlohmann::json j = nlohmann::json::parse(std::ifstream(run / rf::kRun));
    EXPECT_EQ(j.at(rf::run_key::kFrontend), "rtabmap");
    EXPECT_EQ(j.at(rf::run_key::kWifi), wifi);
    EXPECT_EQ(j.at("edge_acceptance"), "best+graph_consistent");
    const nlohmann::json& memory = j.at("frontend_summary").at("memory");
    const int keyframes = j.at("keyframes");
    EXPECT_EQ(
        memory.at("stm").get<int>() + memory.at("wm").get<int>() + memory.at("ltm").get<int>(),
        keyframes);
    EXPECT_EQ(j.at("options").at("time_threshold_ms"), "inf");
    EXPECT_EQ(memory.at("transferred"), 0);  // no threshold: nothing moves

    return j;
  }

  static void check_node_schedule(const fs::path& run, const nlohmann::json& j, int keyframes) {
    namespace rf = run_folder;
    // Nodes on RTAB-Map's schedule (Rtabmap/DetectionRate 1 Hz): closer than 1 s apart only
    // where tracking against the last node failed and the last tracked frame became one.
    std::ifstream kf_file(run / rf::kKeyframes);
    std::vector<double> node_times_s;
    for (std::string kf_line; std::getline(kf_file, kf_line);) {
      if (!kf_line.empty() && kf_line[0] != '#') node_times_s.push_back(std::stod(kf_line));
    }
    ASSERT_EQ(static_cast<int>(node_times_s.size()), keyframes);
    int early_nodes = 0;
    for (std::size_t k = 1; k < node_times_s.size(); ++k) {
      if (node_times_s[k] - node_times_s[k - 1] < 1.0 - 1e-3) ++early_nodes;
    }
    EXPECT_LE(early_nodes, j.at("keyframes_after_tracking_loss").get<int>());
    EXPECT_LT(early_nodes, keyframes / 2);
  }

  static void check_memory_csv(const fs::path& run, const nlohmann::json& j, int keyframes) {
    namespace rf = run_folder;
    // One CSV row per node, with the header of core/run_format.hpp.
    // The loop-closure share of the cost model (likelihood, posterior, loop hypothesis
    // verification) sums over the rows to run.json's figure, and is part of each node's cost.
    std::ifstream csv(run / slam::frontend::rtabmap::rtabmap_memory_csv::kFileName);
    std::string header, line;
    std::getline(csv, header);
    EXPECT_EQ(header + "\n",
              rf::csv_header(slam::frontend::rtabmap::rtabmap_memory_csv::column::kAll));
    const auto column = [](const char* name) {
      const auto& all = slam::frontend::rtabmap::rtabmap_memory_csv::column::kAll;
      return static_cast<std::size_t>(
          std::find_if(all.begin(), all.end(),
                       [&](const char* c) { return std::string(c) == name; }) -
          all.begin());
    };
    int rows = 0;
    double loop_closure_cost_ms = 0.0, likelihood_posterior_cpu_ms = 0.0;
    while (std::getline(csv, line)) {
      std::vector<std::string> cells;
      std::stringstream row(line);
      for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
      ASSERT_EQ(cells.size(), slam::frontend::rtabmap::rtabmap_memory_csv::column::kAll.size())
          << line;
      const double lc_ms = std::stod(cells[column("loop_closure_cost_ms")]);
      EXPECT_LE(lc_ms, std::stod(cells[column("cost_ms")]) + 1e-4) << line;
      EXPECT_LE(std::stoi(cells[column("loop_verifications")]),
                std::stoi(cells[column("verifications")]));
      loop_closure_cost_ms += lc_ms;
      likelihood_posterior_cpu_ms += std::stod(cells[column("likelihood_cpu_ms")]) +
                                     std::stod(cells[column("posterior_cpu_ms")]);
      ++rows;
    }
    EXPECT_EQ(rows, keyframes);
    const nlohmann::json& lc_time = j.at("frontend_summary").at("loop_closure_time_s");
    EXPECT_GT(lc_time.at("cost").get<double>(), 0.0);
    EXPECT_NEAR(lc_time.at("cost").get<double>(), loop_closure_cost_ms * 1e-3, rows * 1e-7);
    EXPECT_NEAR(lc_time.at("likelihood_posterior_cpu").get<double>(),
                likelihood_posterior_cpu_ms * 1e-3, rows * 1e-7);
  }

  /// eval accepts the run folder and scores it: no wrong-place closure on this loop.
  static void check_eval(const fs::path& run, bool wifi, const nlohmann::json& j, int keyframes) {
    namespace rf = run_folder;
    const test::CliResult eval = test::run_wifislam(
        "eval " + run.string() + " --gt " + dataset_.string() + " --set revisit_min_path_m=8",
        dir_);
    ASSERT_EQ(eval.exit_code, 0) << eval.err;
    const nlohmann::json m = nlohmann::json::parse(std::ifstream(run / "eval" / "metrics.json"));
    std::printf("rtabmap%s: %d keyframes, ATE RMSE %.3f m, loop closures online: %s\n",
                wifi ? "+wifi" : "", keyframes, m["trajectory"]["ate_rmse_m"].get<double>(),
                m["loop_closures"]["online"].dump().c_str());
    // The loop has no look-alike walls: the revisit is found, passes the graph-consistency check
    // (RGBD/OptimizeMaxError 3 measured against each link's marginal standard deviations), and
    // every accepted closure joins the right place.
    const nlohmann::json& online = m["loop_closures"]["online"];
    EXPECT_GT(online["scored"].get<int>(), 0);
    EXPECT_EQ(online["wrong_place"].get<int>() + online["far_wrong_place"].get<int>(), 0);
    EXPECT_EQ(online["false_negatives"].get<int>(), 0);
    EXPECT_GT(m["trajectory"]["ate_rmse_m"].get<double>(), 0.0);
    EXPECT_LT(m["trajectory"]["ate_rmse_m"].get<double>(), 0.15);
    // The deterministic cost model's total reaches eval (compare's cost-model table).
    const double cost_s = j.at("frontend_summary").at("node_time_s").at("cost").get<double>();
    EXPECT_GT(cost_s, 0.0);
    EXPECT_EQ(m.at("cost_model_s").get<double>(), cost_s);
    EXPECT_EQ(m.at("loop_closure_cost_s").get<double>(),
              j.at("frontend_summary").at("loop_closure_time_s").at("cost").get<double>());
  }

  static fs::path dir_;
  static bool generated_;
  static inline fs::path dataset_;
};

fs::path RtabmapEndToEnd::dir_;
bool RtabmapEndToEnd::generated_ = false;

TEST_F(RtabmapEndToEnd, VanillaRunWritesAValidRunFolderThatEvalAccepts) { run_and_check(false); }

TEST_F(RtabmapEndToEnd, WifiRunWritesAValidRunFolderThatEvalAccepts) { run_and_check(true); }

}  // namespace
}  // namespace wifislam
