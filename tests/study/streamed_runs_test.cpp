// The comparison runner feeds our SLAM runs while it writes their dataset (study/streamed_runs):
// each run must be the run a reader of the finished dataset gets, byte for byte, whether it ran
// side by side with the generation (jobs 2) or on a second rendering (jobs 1: the Wi-Fi run);
// and a study's depth-only dataset must score the runs exactly as the full dataset does.
// The demo scene at 3 fps: frame stamps that are not whole milliseconds, Wi-Fi scans, odometry.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "apps/demo_scene.hpp"
#include "core/error.hpp"
#include "sim/generate/sensor_input.hpp"
#include "sim/scene/scene_loader.hpp"
#include "slam/io/run_folder_writer.hpp"
#include "slam/system/run_slam.hpp"
#include "study/comparison_study.hpp"
#include "tests/support/read_file.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::study {
namespace {

namespace fs = std::filesystem;

/// "" when equal, else the first line where they differ (the files are long).
std::string first_difference(const std::string& a, const std::string& b) {
  std::istringstream in_a(a), in_b(b);
  std::string line_a, line_b;
  for (int line = 1;; ++line) {
    const bool more_a = static_cast<bool>(std::getline(in_a, line_a));
    const bool more_b = static_cast<bool>(std::getline(in_b, line_b));
    if (!more_a && !more_b) return "";
    if (more_a != more_b || line_a != line_b)
      return "line " + std::to_string(line) + ": '" + line_a + "' against '" + line_b + "'";
  }
}

const char* const kRunFiles[] = {"trajectory.txt", "keyframes.txt", "graph.json",
                                 "loop_closures.csv"};

class StreamedRuns : public ::testing::Test {
 protected:
  void SetUp() override { scratch_ = test::scratch_folder(); }

  ComparisonResult compare(const std::string& name, int jobs, bool colour) {
    ComparisonOptions options("rgbdslam", {"min_matches=10"});
    options.fps = 3;
    options.max_frames = 150;
    options.jobs = jobs;
    options.plots = false;
    options.dataset_colour = colour;
    fs::create_directories(scratch_ / name);
    return run_comparison({sim::scene::load_scene_yaml(cli::kDemoSceneYaml, "<demo scene>")},
                          options, scratch_ / name);
  }

  fs::path scratch_;
};

TEST_F(StreamedRuns, RunsFedAsTheDatasetIsWrittenAreTheRunsOfItsReader) {
  // jobs 1: vanilla reads the generation's events, Wi-Fi a second rendering in memory.
  const ComparisonResult one = compare("jobs1", 1, /*colour=*/true);
  ASSERT_EQ(one.cases.size(), 2u);
  for (const ComparisonCase& c : one.cases) {
    SCOPED_TRACE(c.run_dir.string());
    sim::generate::SensorInputOptions input;
    const fs::path dataset =
        scratch_ / "jobs1" / "datasets" / c.run_dir.parent_path().parent_path().filename();
    const sim::generate::SensorInput reader =
        sim::generate::open_sensor_input(dataset, input);  // checksums verified
    slam::SlamOptions options;
    slam::set_option(options, "min_matches", "10");
    options.seed = c.seed;
    options.wifi.enabled = c.wifi;
    slam::system::RunSummary summary;
    const auto system = slam::system::run_slam(*reader.stream, options, summary);
    const fs::path by_reader = scratch_ / (c.wifi ? "reader_wifi" : "reader_vanilla");
    slam::io::write_run_folder(by_reader, *system, summary, false);
    EXPECT_GT(summary.keyframes, 10);
    for (const char* file : kRunFiles) {
      const std::string streamed = test::read_file(scratch_ / "jobs1" / c.run_dir / file);
      EXPECT_FALSE(streamed.empty()) << file;
      EXPECT_EQ(first_difference(streamed, test::read_file(by_reader / file)), "") << file;
    }
    if (c.wifi) {
      EXPECT_EQ(
          first_difference(test::read_file(scratch_ / "jobs1" / c.run_dir / "wifi_clusters.csv"),
                           test::read_file(by_reader / "wifi_clusters.csv")),
          "");
    }
  }

  // jobs 2 and a depth-only dataset (a study's): both runs side by side with the generation.
  const ComparisonResult two = compare("jobs2", 2, /*colour=*/false);
  ASSERT_EQ(two.cases.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const ComparisonCase &a = one.cases[i], &b = two.cases[i];
    SCOPED_TRACE(b.run_dir.string());
    ASSERT_EQ(a.run_dir, b.run_dir);
    for (const char* file : kRunFiles) {
      EXPECT_EQ(first_difference(test::read_file(scratch_ / "jobs1" / a.run_dir / file),
                                 test::read_file(scratch_ / "jobs2" / b.run_dir / file)),
                "")
          << file;
    }
    // Scored alike: the evaluation's overlap test read the same depth images.
    EXPECT_EQ(a.evaluation.ate_rmse_m, b.evaluation.ate_rmse_m);
    EXPECT_EQ(a.evaluation.loop_closures_detected, b.evaluation.loop_closures_detected);
    EXPECT_EQ(a.evaluation.loop_closures_correct, b.evaluation.loop_closures_correct);
    EXPECT_EQ(a.evaluation.false_positives, b.evaluation.false_positives);
    EXPECT_EQ(a.evaluation.revisit_episodes, b.evaluation.revisit_episodes);
    EXPECT_EQ(a.evaluation.false_negatives, b.evaluation.false_negatives);
    EXPECT_TRUE(b.evaluation.overlap_used_depth) << b.evaluation.overlap_method;
    EXPECT_EQ(a.evaluation.overlap_method, b.evaluation.overlap_method);
  }
  const fs::path depth_only = scratch_ / "jobs2" / "datasets" / "twin_corridors-seed8";
  ASSERT_TRUE(fs::is_directory(depth_only / "depth")) << depth_only;
  EXPECT_FALSE(fs::exists(depth_only / "rgb"));
  EXPECT_FALSE(fs::exists(depth_only / "rgb.txt"));
  EXPECT_NE(test::read_file(depth_only / "manifest.json").find("\"colour_images\": false"),
            std::string::npos);
  try {
    (void)sim::generate::open_sensor_input(depth_only, {});
    FAIL() << "SLAM input opened a depth-only dataset";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("depth images only"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace wifislam::study
