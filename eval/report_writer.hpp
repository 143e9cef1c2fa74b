#pragma once
// Writes one run's evaluation as a folder (atomically: <out>.partial, renamed when complete):
//   report.md     for people: the numbers, the thresholds, every loop closure's verdict
//   metrics.json  everything, thresholds included
//   metrics.csv   one header line and one row of flat scalars (for spreadsheets and sweeps)
//   trajectory.{png,svg}, ate_along_path.{png,svg}, and wifi_clusters.{png,svg} for Wi-Fi runs

#include <filesystem>
#include <string>

#include "eval/run_evaluation.hpp"

namespace wifislam::eval {

/// The timestamp association rule, as report.md and `wifislam eval --help` state it.
extern const char* const kAssociationRule;

/// Replaces an existing `out_dir`. `plots` false: text files only. The floor plan behind the plots
/// is the dataset's scene.yaml, generated; without one the plots show the paths alone (and the
/// report says so). Throws IoError when the folder cannot be written.
void write_evaluation(const std::filesystem::path& out_dir, const RunEvaluation& evaluation,
                      const std::filesystem::path& run_dir,
                      const std::filesystem::path& dataset_dir, bool plots);

/// The report.md text. `notes` are added under "Notes" (plot backdrop and the like).
std::string render_report_markdown(const RunEvaluation& evaluation,
                                   const std::vector<std::string>& notes);

/// The metrics.csv text: header + one row, RFC 4180 quoting where needed.
std::string render_metrics_csv(const RunEvaluation& evaluation);

}  // namespace wifislam::eval
