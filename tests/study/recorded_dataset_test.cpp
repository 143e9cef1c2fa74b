// A dataset generated once for many runs (study/recorded_dataset.hpp): each run replayed from its
// recorded events and shared features writes the run folder a reader of the finished dataset
// writes, byte for byte (timing.json aside), for two front ends with their own settings, vanilla
// and Wi-Fi; and its timing charges the extraction. The demo scene at 3 fps, 150 frames.

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <mutex>

#include <nlohmann/json.hpp>

#include "apps/demo_scene.hpp"
#include "sim/generate/generation_pipeline.hpp"
#include "sim/generate/sensor_input.hpp"
#include "sim/scene/scene_loader.hpp"
#include "slam/io/run_folder_writer.hpp"
#include "slam/system/run_slam.hpp"
#include "study/recorded_dataset.hpp"
#include "tests/support/read_file.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::study {
namespace {

namespace fs = std::filesystem;

using test::read_file;

TEST(RecordedDataset, ReplayedRunsAreTheRunsOfTheDatasetsReader) {
  const fs::path scratch = test::scratch_folder();
  sim::generate::GenerateOptions overrides;
  overrides.fps = 3;
  const auto site = std::make_shared<const sim::site::Site>(sim::generate::resolve_scene(
      sim::scene::load_scene_yaml(cli::kDemoSceneYaml, "<demo scene>"), overrides));
  sim::generate::GenerateOptions generate;
  generate.max_frames = 150;

  std::vector<StreamedRun> runs;
  for (const char* frontend : {"rgbdslam", "orbslam"}) {
    for (bool wifi : {false, true}) {
      StreamedRun run;
      run.slam.frontend = frontend;
      slam::set_option(run.slam, "min_matches", "15");
      run.slam.seed = site->scene().seed;
      run.slam.wifi.enabled = wifi;
      run.run_dir = scratch / (std::string(frontend) + (wifi ? "_wifi" : "_vanilla"));
      runs.push_back(std::move(run));
    }
  }
  std::vector<slam::feature::FeatureOptions> features;
  for (const StreamedRun& run : runs) features.push_back(run.slam.features);
  const RecordedDataset dataset(site, scratch / "dataset", generate, features, 2);
  EXPECT_EQ(dataset.summary().frames, 150);
  ASSERT_NE(dataset.features(runs.front().slam.features), nullptr);
  EXPECT_EQ(dataset.features(runs.front().slam.features)->size(), 150u);
  std::vector<std::size_t> done;
  std::mutex mutex;
  run_recorded(dataset, runs, 2, [&](std::size_t i) {
    std::lock_guard lock(mutex);
    done.push_back(i);
  });
  EXPECT_EQ(done.size(), runs.size());

  for (StreamedRun& run : runs) {
    SCOPED_TRACE(run.run_dir.filename().string());
    const sim::generate::SensorInput reader =
        sim::generate::open_sensor_input(scratch / "dataset", {});
    slam::system::RunSummary summary;
    const auto system = slam::system::run_slam(*reader.stream, run.slam, summary);
    const fs::path by_reader = run.run_dir.string() + "_reader";
    slam::io::write_run_folder(by_reader, *system, summary, false);
    EXPECT_GT(summary.keyframes, 5);
    for (const char* file :
         {"trajectory.txt", "keyframes.txt", "graph.json", "loop_closures.csv"}) {
      const std::string replayed = test::read_file(run.run_dir / file);
      EXPECT_FALSE(replayed.empty()) << file;
      EXPECT_EQ(replayed, test::read_file(by_reader / file)) << file;
    }
    if (run.slam.wifi.enabled) {
      EXPECT_EQ(test::read_file(run.run_dir / "wifi_clusters.csv"),
                test::read_file(by_reader / "wifi_clusters.csv"));
    }
    // The extraction is charged: one call per frame, as in the reader's run.
    const auto timing = nlohmann::json::parse(test::read_file(run.run_dir / "timing.json"));
    const auto& extraction = timing["modules"]["feature_extraction"];
    EXPECT_EQ(extraction["calls"], 150);
    EXPECT_GT(extraction["total_s"].get<double>(), 0.0);
  }
  // A run whose features were not extracted is refused before any run starts.
  std::vector<StreamedRun> other(1);
  other[0].slam.features.max_keypoints = 123;
  other[0].run_dir = scratch / "other";
  EXPECT_THROW(run_recorded(dataset, other, 1), std::invalid_argument);
  EXPECT_FALSE(fs::exists(scratch / "other"));
  fs::remove_all(scratch);
}

}  // namespace
}  // namespace wifislam::study
