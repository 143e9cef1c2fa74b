#pragma once
// One dataset generated once for many SLAM runs: its events kept in memory and every frame's
// features extracted once per FeatureOptions, so that the runs on it (a sweep of settings and
// front ends, vanilla and Wi-Fi) neither render nor extract again. The paper's runs share each
// twin's rendering this way (study/paper/paper_runner.hpp).
//
// Memory: the recorded frames carry no images, only their features (about 85 bytes a keypoint:
// 200 MB for 2 300 frames of 1 000 keypoints, per FeatureOptions). The dataset written to disk is
// what the evaluation reads (depth, for the overlap test; colour when asked).
//
// A run on it (run_recorded) writes the run folder a run reading the finished dataset writes,
// byte for byte, but for timing.json (feature extraction is charged as measured when the store
// was filled: slam/feature/feature_store.hpp).

#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

#include "core/sensor_stream.hpp"
#include "core/sensor_stream_fanout.hpp"
#include "sim/generate/generate_options.hpp"
#include "sim/site/site.hpp"
#include "slam/feature/feature_store.hpp"
#include "study/streamed_runs.hpp"

namespace wifislam::study {

class RecordedDataset {
 public:
  /// Generates `site`'s dataset into `dataset_dir` (`generate.on_event` must be unset) and
  /// records its events, extracting each frame's features for every entry of `features` on up to
  /// `threads` threads while the generation goes on. Rethrows the generation's failure.
  RecordedDataset(std::shared_ptr<const sim::site::Site> site,
                  const std::filesystem::path& dataset_dir, sim::generate::GenerateOptions generate,
                  std::vector<slam::feature::FeatureOptions> features, int threads);
  ~RecordedDataset();
  RecordedDataset(const RecordedDataset&) = delete;
  RecordedDataset& operator=(const RecordedDataset&) = delete;

  const sim::generate::GenerateSummary& summary() const { return summary_; }
  const std::filesystem::path& dataset_dir() const { return dataset_dir_; }
  /// A stream of the recorded events, for one run (frames carry no images).
  std::unique_ptr<SensorStream> stream() const;
  /// The features made with `options`, or nullptr when they were not extracted.
  const slam::feature::FeatureStore* features(const slam::feature::FeatureOptions& options) const;

 private:
  class Replay;
  std::filesystem::path dataset_dir_;
  SensorStreamFacts facts_;
  std::vector<SensorEvent> events_;
  std::vector<std::unique_ptr<slam::feature::FeatureStore>> stores_;
  sim::generate::GenerateSummary summary_;
};

/// Runs every run of `runs` on `dataset`'s recorded events, `jobs` at a time; each run's
/// FeatureOptions must be among the dataset's (std::invalid_argument otherwise, before any run).
/// `on_run_done(i)` is called from the run's thread once runs[i]'s folder is written. Rethrows
/// the first run's failure after every run has stopped.
void run_recorded(const RecordedDataset& dataset, std::vector<StreamedRun>& runs, int jobs,
                  const std::function<void(std::size_t)>& on_run_done = {});

}  // namespace wifislam::study
