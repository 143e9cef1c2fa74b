#pragma once
// Writes one run's evaluation as a folder (atomically: <out>.partial, renamed when complete):
//   report.md     for people: the numbers, the thresholds, every loop closure's verdict
//   metrics.json  everything, thresholds included
//   metrics.csv   one header line and one row of flat scalars (for spreadsheets and sweeps)
//   trajectory.{png,svg}, ate_along_path.{png,svg}, and wifi_clusters.{png,svg} for Wi-Fi runs

#include <filesystem>
#include <string>

#include "eval/run_evaluation.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::eval {

/// The timestamp association rule, as report.md and `wifislam eval --help` state it.
extern const char* const kAssociationRule;

/// What the plots draw under the paths: the floor plan of the dataset's world, when the caller has
/// it (a comparison holds the site it generated the dataset from; `wifislam eval` builds the world
/// from the dataset's scene.yaml: sim::dataset_world), else nothing, with the reason, which
/// report.md notes.
struct PlanBackdrop {
  const sim::world::FloorPlan* plan = nullptr;
  std::string missing_reason;
};

/// Replaces an existing `out_dir`. `plots` false: text files only. Throws IoError when the folder
/// cannot be written.
void write_evaluation(const std::filesystem::path& out_dir, const RunEvaluation& evaluation,
                      bool plots, const PlanBackdrop& backdrop);

/// The report.md text. `notes` are added under "Notes" (plot backdrop and the like).
std::string render_report_markdown(const RunEvaluation& evaluation,
                                   const std::vector<std::string>& notes);

/// The metrics.csv text: header + one row, RFC 4180 quoting where needed.
std::string render_metrics_csv(const RunEvaluation& evaluation);

}  // namespace wifislam::eval
