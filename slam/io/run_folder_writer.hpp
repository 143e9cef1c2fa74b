#pragma once
// Writes the SLAM run folder (its files, keys and names: core/run_format.hpp) into <dir>.partial/
// and renames it when complete; the front end adds its own files (e.g. wifi_clusters.csv).

#include <filesystem>

#include <nlohmann/json.hpp>

#include "slam/system/run_summary.hpp"
#include "slam/system/slam_system.hpp"

namespace wifislam::slam::io {

nlohmann::json graph_to_json(const graph::PoseGraph& graph);
std::string loop_closures_csv(const system::SlamSystem& system);

/// Writes the run folder of a finished system. `extra_run_info` is merged into run.json.
void write_run_folder(const std::filesystem::path& run_dir, const system::SlamSystem& system,
                      const system::RunSummary& summary, bool overwrite,
                      const nlohmann::json& extra_run_info = nlohmann::json::object());

}  // namespace wifislam::slam::io
