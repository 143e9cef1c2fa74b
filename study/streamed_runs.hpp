#pragma once
// SLAM runs fed while their dataset is generated: each run takes the frames, scans and odometry
// in memory, exactly as it would read them back from the dataset being written
// (sim::generate::GenerateOptions::on_event), so the runs of one dataset share one rendering and
// decode no PNG. Up to `jobs` runs go side by side with the generation (one SensorStreamFanout);
// further runs go in groups of up to `jobs`, each group on the same site rendered again in memory
// (sim::generate::GeneratorStream: rendering a frame costs less than decoding its two PNGs). Every
// run writes the run folder it would write reading the finished dataset, byte for byte.

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/generate/generate_options.hpp"
#include "sim/site/site.hpp"
#include "slam/slam_options.hpp"
#include "slam/system/run_summary.hpp"

namespace wifislam::study {

/// One of our SLAM front ends on the dataset (an external system reads the dataset's files).
struct StreamedRun {
  slam::SlamOptions slam;
  std::filesystem::path run_dir;  // written by slam::write_run_folder; must not exist
  nlohmann::json run_info = nlohmann::json::object();  // merged into run.json ("input": ...)
  slam::system::RunSummary summary;                    // filled in by generate_with_runs
};

/// Generates `site`'s dataset into `dataset_dir` (generate.on_event must be unset: this sets it)
/// and runs every run of `runs` on its events, `jobs` at a time. `on_run_done(i)` is called from
/// the run's thread once runs[i]'s folder is written. Rethrows the first failure (the
/// generation's, else a run's) after every thread has stopped.
sim::generate::GenerateSummary generate_with_runs(
    std::shared_ptr<const sim::site::Site> site, const std::filesystem::path& dataset_dir,
    sim::generate::GenerateOptions generate, std::vector<StreamedRun>& runs, int jobs,
    const std::function<void(std::size_t)>& on_run_done = {});

}  // namespace wifislam::study
