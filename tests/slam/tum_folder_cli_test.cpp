// `wifislam slam` through the command line on a plain TUM RGB-D folder (images and their lists,
// no Wi-Fi, odometry, calibration or manifest), as the TUM benchmark ships its sequences.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/tum_trajectory.hpp"
#include "sim/generate/dataset_writer.hpp"
#include "tests/slam/slam_test_scene.hpp"
#include "tests/support/cli_run.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;

TEST(RgbdslamEndToEnd, RunsOnAPlainTumFolderWithoutWifi) {
  const fs::path root = test::scratch_folder();
  const fs::path generated = root / "generated";
  sim::generate::GenerateOptions generate;
  generate.fps = 5.0;
  generate.max_frames = 40;
  generate.threads = 1;
  sim::generate::generate_dataset(test::small_loop_scene(), generated, generate);
  // A plain TUM RGB-D layout: images and their lists only (no wifi.csv, odometry, calibration,
  // manifest).
  const fs::path tum = root / "tum";
  fs::create_directories(tum);
  for (const char* item : {"rgb", "depth", "rgb.txt", "depth.txt"}) {
    fs::copy(generated / item, tum / item, fs::copy_options::recursive);
  }
  const fs::path run = root / "run";
  const test::CliResult slam = test::run_wifislam(
      "slam " + tum.string() + " --frontend rgbdslam --set max_keypoints=400 -o " + run.string(),
      root);
  ASSERT_EQ(slam.exit_code, 0) << slam.err;
  for (const char* file : {"trajectory.txt", "keyframes.txt", "graph.json", "loop_closures.csv",
                           "timing.json", "run.json"}) {
    EXPECT_TRUE(fs::exists(run / file)) << file;
  }
  EXPECT_EQ(read_tum_trajectory((run / "trajectory.txt").string()).size(), 40u);
  std::ifstream run_json(run / "run.json");
  const nlohmann::json j = nlohmann::json::parse(run_json);
  EXPECT_EQ(j.at("stream").at("has_wifi"), false);
  EXPECT_EQ(j.at("frames"), 40);
  std::ifstream timing_json(run / "timing.json");
  const nlohmann::json timing = nlohmann::json::parse(timing_json);
  EXPECT_GT(timing.at("counters").at("ransac_runs").get<int>(), 0);
  EXPECT_TRUE(timing.at("modules").contains("feature_extraction"));
}

}  // namespace
}  // namespace wifislam
