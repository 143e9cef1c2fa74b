#pragma once
// Evaluates a run folder (written by `wifislam slam`: trajectory.txt, keyframes.txt, graph.json,
// loop_closures.csv, timing.json, run.json, and wifi_clusters.csv for Wi-Fi runs) or a bare TUM
// trajectory file (another system's CameraTrajectory.txt) against a dataset folder's exact
// ground truth (groundtruth.txt, depth.txt + depth/, calibration.yaml). Only the trajectory is
// required: without keyframes.txt and graph.json / loop_closures.csv the loop closures are "not
// available", without timing.json the timing is, and the evaluation says so. Reads files only:
// works on any run folder in this format and never links the SLAM library.

#include <filesystem>
#include <string>

#include "core/tum_trajectory.hpp"
#include "eval/eval_options.hpp"
#include "eval/run_evaluation.hpp"

namespace wifislam::eval {

/// The fewest poses an estimate and its ground truth must share: the alignment (Umeyama) needs
/// three.
inline constexpr std::size_t kMinAssociatedPoses = 3;

/// `run_or_trajectory`: a run folder, or a TUM trajectory file. Throws IoError for a missing or
/// unreadable file and ParseError naming file:line (and key) for malformed content (e.g. a NaN in
/// trajectory.txt, a graph.json edge without "from_to"); InvalidInputError when the estimate and
/// the ground truth have fewer than 3 poses in common. `verify_checksums`: whether the ground
/// truth must match the dataset's manifest.json (as `slam`'s reading of the dataset).
RunEvaluation evaluate_run(const std::filesystem::path& run_or_trajectory,
                           const std::filesystem::path& dataset_dir, const EvalOptions& options,
                           bool verify_checksums = true);

/// The trajectory part of evaluate_run (ATE, RPE, the aligned path) for two trajectories held in
/// memory, associated and aligned exactly as evaluate_run does it (the Python module's evaluate
/// of arrays). Loop closures and timing are "not available". The names stand for the two in
/// errors. Throws InvalidInputError when fewer than 3 poses share a stamp.
RunEvaluation evaluate_trajectory(const Trajectory& estimated, const Trajectory& ground_truth,
                                  const EvalOptions& options, const std::string& estimate_name,
                                  const std::string& ground_truth_name);

}  // namespace wifislam::eval
