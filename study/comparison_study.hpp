#pragma once
// The paper's experiment as one call: for each scene and seed, generate a dataset once, run the
// front end vanilla and with Wi-Fi for every combination of swept settings, evaluate every run
// against exact ground truth, and tabulate (rows: scenes; columns: setting x {Vanilla, WiFi}) the
// metrics of the paper's "RGBD SLAM performance" section.
//
// Folder written (under the caller's folder, which the caller commits atomically):
//   datasets/<scene>-seed<seed>/                 TUM-layout dataset (readable by other tools)
//   runs/<scene>-seed<seed>/<setting>/<variant>/ SLAM run folder + eval/ (report, plots)
//   comparison.md, comparison.csv, comparison.json

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/final_paths.hpp"
#include "eval/eval_options.hpp"
#include "eval/run_evaluation.hpp"
#include "sim/scene/scene.hpp"
#include "sim/site/site.hpp"
#include "slam/slam_options.hpp"

namespace wifislam::study {

/// One swept SLAM option: `key` takes each of `values` in turn.
struct SweepAxis {
  std::string key;
  std::vector<std::string> values;
};

/// Parses "min_matches=10,15,20"; throws ParseError naming the text when malformed or when the
/// key is not a SLAM option (the values are checked when the runs are set up, before any work).
SweepAxis parse_sweep(const std::string& text);

struct ComparisonOptions {
  ComparisonOptions() = default;
  /// The front end and the SLAM options of every run from `key=value` assignments, parsed here
  /// once (ParseError naming a bad one); they label the columns too.
  ComparisonOptions(const std::string& frontend, const std::vector<std::string>& assignments);

  /// The options every run starts from, front end included; the swept options and the variant's
  /// Wi-Fi switch are set on top. Its seed is each dataset's seed unless `slam_seed_set`.
  slam::SlamOptions slam;
  bool slam_seed_set = false;
  /// The options that differ from the defaults as the user gave them ("min_matches=10"): the
  /// column label and the runs' folder names; none: "defaults".
  std::vector<std::string> settings;
  /// Swept options; every combination (cartesian product) is one setting. None: one setting,
  /// the defaults.
  std::vector<SweepAxis> sweeps;
  /// Seeds per scene: the scene's own seed, then seed + 1, ... Each seed is a different world
  /// texture, AP placement, noise and pause draw; the SLAM's random draws use it too.
  int seeds = 1;
  /// Dataset frame rate (default: each scene's) and length (< 0: the whole route).
  std::optional<double> fps;
  std::int64_t max_frames = -1;
  eval::EvalOptions eval;
  bool plots = true;
  /// SLAM runs in parallel, side by side on one rendering of their dataset (and evaluations).
  /// 1 keeps the wall-clock figures free of interference (the timing columns compare runs);
  /// results are identical for any value.
  int jobs = 1;
  /// Write the datasets' colour images. false (a study, which deletes its datasets): depth only,
  /// all the evaluation reads; our SLAM runs take their frames in memory either way. An external
  /// system's dataset always has colour.
  bool dataset_colour = true;
  /// One line per finished step (dataset generated, run evaluated), from any worker thread
  /// (calls are serialised).
  std::function<void(const std::string&)> on_progress;
};

struct ComparisonCase {
  std::string scene;
  std::uint64_t seed = 0;
  std::string setting;  // options set by --set and --sweep ("min_matches=10 ...") or "defaults"
  bool wifi = false;
  std::filesystem::path run_dir;      // relative to the output folder
  std::filesystem::path dataset_dir;  // the dataset it ran on, relative to the output folder
  /// "ok", or why an external system's run gave no evaluation (interop/external_run.hpp): such a
  /// case is listed with its status and counts in no table.
  std::string status = "ok";
  eval::RunEvaluation evaluation;
};

/// Where the Wi-Fi run of one scene, seed and setting first differs from its vanilla twin
/// (eval/run_divergence.hpp); keyframe -1 = nowhere.
struct PairDivergence {
  std::string scene;
  std::uint64_t seed = 0;
  std::string setting;
  std::int64_t keyframe = -1;
  double time_s = 0.0;
};

struct ComparisonResult {
  std::vector<std::string> scenes;    // row order
  std::vector<std::string> settings;  // column order
  int seeds = 1;
  std::vector<ComparisonCase> cases;
  std::vector<PairDivergence> divergences;
  /// The site each dataset was generated from, per scene and seed in row order (scene's own seed
  /// first): callers draw its plan or radio map without building it again.
  std::vector<std::shared_ptr<const sim::site::Site>> sites;

  /// The paper-style tables (one per metric) in Markdown; metrics averaged over seeds, counts
  /// summed.
  std::string markdown() const;
  /// One row per case, every flat metric of the evaluation (long format, for pandas & co).
  std::string csv() const;
  nlohmann::json to_json() const;
};

/// The user's files the runs read (front_end_choice.hpp, files_read_by), over every swept
/// setting: the output folder must not hold them. Throws as the runs' option checks do.
std::vector<std::filesystem::path> comparison_input_files(const ComparisonOptions& options);

/// Whether "key=value" assignments set the SLAM's seed (then every run draws from it).
bool assigns_slam_seed(const std::vector<std::string>& assignments);

/// Runs the whole comparison, writing into `out_dir` (which must exist). Throws on bad input
/// before any heavy work (unknown option key, bad value). When `out_dir` is a folder under
/// construction (AtomicDirectory), `finals` says where it will be: the evaluations and external
/// runs name those paths.
ComparisonResult run_comparison(const std::vector<sim::scene::Scene>& scenes,
                                const ComparisonOptions& options,
                                const std::filesystem::path& out_dir,
                                const FinalPaths& finals = {});

}  // namespace wifislam::study
