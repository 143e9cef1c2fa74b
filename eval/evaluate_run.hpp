#pragma once
// Evaluates a run folder (written by `wifislam slam`: trajectory.txt, keyframes.txt,
// loop_closures.csv, timing.json, run.json, and wifi_clusters.csv for Wi-Fi runs) against a
// dataset folder's exact ground truth (groundtruth.txt, depth.txt + depth/, calibration.yaml).
// Reads files only: works on any run folder in this format and never links the SLAM library.

#include <filesystem>

#include "eval/eval_options.hpp"
#include "eval/run_evaluation.hpp"

namespace wifislam::eval {

/// Throws IoError for a missing or unreadable file and ParseError naming file:line (and key) for
/// malformed content (e.g. a NaN in trajectory.txt); InvalidInputError when the run and the
/// ground truth have fewer than 3 poses in common.
RunEvaluation evaluate_run(const std::filesystem::path& run_dir,
                           const std::filesystem::path& dataset_dir, const EvalOptions& options);

}  // namespace wifislam::eval
