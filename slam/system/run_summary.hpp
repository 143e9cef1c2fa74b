#pragma once
// What a SLAM run did, Ceres style: counts, where the time went, and a human-readable report.

#include <cstdint>
#include <map>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "slam/optimize/pose_graph_optimizer.hpp"

namespace wifislam::slam::system {

class SlamSystem;

struct RunSummary {
  std::string input;     // the stream's description
  std::string frontend;  // the front end's name ("rgbdslam")
  bool wifi = false;     // the front end held a Wi-Fi module
  std::int64_t frames = 0, keyframes = 0;
  std::int64_t visual_edges = 0, loop_edges = 0, odometry_edges = 0, weak_edges = 0;
  std::int64_t keyframes_after_tracking_loss = 0;
  std::int64_t tracking_failures = 0, candidate_comparisons = 0, ransac_runs = 0;
  double wall_s = 0.0;        // processing time, reading the input included
  double processing_s = 0.0;  // time inside the pipeline (the "total" module)
  std::map<std::string, double> module_s;
  optimize::OptimisationSummary final_optimisation;

  /// Frames per second of the pipeline alone (processing_s), and including input (wall_s).
  double pipeline_fps() const { return processing_s > 0 ? frames / processing_s : 0.0; }
  double wall_fps() const { return wall_s > 0 ? frames / wall_s : 0.0; }
  /// "rgbdslam" or "rgbdslam+wifi".
  std::string label() const { return frontend + (wifi ? "+wifi" : ""); }

  std::string BriefReport() const;
  std::string FullReport() const;
  nlohmann::json to_json() const;
};

/// Summary of `system` as it stands (call after finish()).
RunSummary summarize(const SlamSystem& system, const std::string& input, double wall_s);

}  // namespace wifislam::slam::system
