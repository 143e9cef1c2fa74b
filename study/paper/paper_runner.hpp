#pragma once
// Runs the paper's plan (paper_plan.hpp) into a paper folder (paper_folder.hpp), resumably: every
// case a study database already holds is skipped, so a second run continues where the first
// stopped and redoes nothing.
//
// The runs of one twin and seed share one rendering (study/recorded_dataset.hpp): its dataset is
// generated once (depth only, for the evaluation), every frame's features are extracted once, and
// every run of every part on it (each setting, vanilla and Wi-Fi) replays them from memory. A run
// is evaluated as soon as it ends, and a case's two rows go into its study's database as soon as
// both its runs are evaluated: a killed `paper` loses at most the cases in flight. The rows are
// those `wifislam study run` writes for the same study file (tested).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "study/paper/paper_numbers.hpp"
#include "study/paper/paper_plan.hpp"

namespace wifislam::study::paper {

struct PaperRunOptions {
  std::filesystem::path folder;
  std::vector<Part> parts = runnable_parts();
  std::vector<std::string> twins = twin_names();
  /// Seeds per twin: its own seed, then seed + 1, ...
  int seeds = 1;
  PaperSettings settings;
  /// SLAM runs at a time (and feature-extraction threads). Results do not depend on it; times
  /// are measured under it (1 keeps them free of interference).
  int jobs = 2;
  /// Run only the twin-and-seed groups whose index in the plan is shard_index modulo shard_count.
  int shard_index = 0, shard_count = 1;
  /// Replace an existing paper folder (one with this tool's marker) instead of continuing it.
  bool force = false;
  std::function<void(const std::string&)> on_progress;
};

struct PaperRunSummary {
  std::int64_t runs = 0;           // SLAM runs made now
  std::int64_t cases_skipped = 0;  // already in their databases
  std::int64_t localisations = 0;  // FAB-MAP comparisons made now
  double wall_s = 0.0;
};

/// Creates the folder (marker, paper.json, the twins' scenes and every planned study file), or
/// checks that an existing one was made by `paper` with the same settings and twins. Throws
/// InvalidInputError naming what differs.
void prepare_paper_folder(const PaperRunOptions& options);

/// prepare_paper_folder, then every unfinished case of the plan (this shard's groups).
PaperRunSummary run_paper(const PaperRunOptions& options);

/// Wall-clock per part (and the shared rendering), summed over every `paper` run into the
/// folder: timing.json.
std::map<std::string, double> paper_part_times(const std::filesystem::path& folder);

}  // namespace wifislam::study::paper
