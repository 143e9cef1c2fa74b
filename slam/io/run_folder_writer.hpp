#pragma once
// The SLAM run folder (DESIGN.md, "Data formats"):
//   trajectory.txt     every frame, TUM (timestamp tx ty tz qx qy qz qw), camera-to-map
//   keyframes.txt      the keyframes, TUM, same frame
//   graph.json         nodes (keyframe id, frame index, time, pose) and edges (type
//                      odometry / visual / loop / weak, relative pose, information, inliers)
//   loop_closures.csv  one row per loop-closure edge
//   timing.json        wall-clock per module, work counters, per-keyframe detection time
//   run.json           options, input, counts
// plus whatever the front end writes (e.g. wifi_clusters.csv). Written into <dir>.partial/ and
// renamed when complete.

#include <filesystem>

#include <nlohmann/json.hpp>

#include "slam/system/run_summary.hpp"
#include "slam/system/slam_system.hpp"

namespace wifislam::slam {

nlohmann::json graph_to_json(const PoseGraph& graph);
std::string loop_closures_csv(const SlamSystem& system);

/// Writes the run folder of a finished system. `extra_run_info` is merged into run.json.
void write_run_folder(const std::filesystem::path& run_dir, const SlamSystem& system,
                      const RunSummary& summary, bool overwrite,
                      const nlohmann::json& extra_run_info = nlohmann::json::object());

}  // namespace wifislam::slam
