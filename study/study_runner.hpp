#pragma once
// Runs a study's cases (all of them, or one shard's) into its SQLite database
// (result_store.hpp), skipping cases the database already holds: a rerun after Ctrl-C or SIGKILL
// continues where the first run stopped and ends with the same rows as an uninterrupted run.
//
// Per case: the base scene with the case's scene axes set (loaded and checked as a scene file),
// the SLAM options with the case's slam.* and frontend axes set; then
//  - level radio: radio_resolution.hpp, one row (variant "radio"), on a site shared with the
//    study's other cases of the same building, route and seed (site_cache.hpp);
//  - level slam: the comparison runner (comparison_study.hpp) on that one scene and seed, vanilla
//    and Wi-Fi, two rows with what `compare` measures. Its dataset and run folders live in a
//    scratch folder beside the database (<database>.work/<case id>) and are removed once the
//    case's rows are written; the images are needed on disk while it runs, because the
//    evaluation's true revisits (false negatives) come from depth-image view overlap.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "eval/run_evaluation.hpp"
#include "sim/scene/scene.hpp"
#include "slam/slam_options.hpp"
#include "study/result_store.hpp"
#include "study/study_file.hpp"

namespace wifislam::study {

struct StudyRunOptions {
  std::filesystem::path database;
  int shard_index = 0, shard_count = 1;
  /// Cases at a time (radio level) or SLAM runs at a time (slam level). Results do not depend on
  /// it.
  int jobs = 1;
  /// Replace the database at `database` (another study's: `study run --force`). It is removed
  /// once every case checks and the database's lock is held, so a refused run removes nothing.
  bool replace_database = false;
  std::function<void(const std::string&)> on_progress;
};

struct StudyRunSummary {
  std::size_t cases = 0;    // in this shard
  std::size_t skipped = 0;  // already in the database
  std::size_t ran = 0;
  double wall_s = 0.0;
};

/// The base scene with the case's scene axes applied. Throws ParseError naming the study file,
/// the case and the axis when a value does not make a valid scene.
sim::scene::Scene case_scene(const StudyFile& study, const StudyCase& c);
/// The case's SLAM options: the study's slam.settings, then its slam.* and frontend axes.
slam::SlamOptions case_slam_options(const StudyFile& study, const StudyCase& c);

/// Checks every case's scene and options (no simulation), so a bad value fails before hours of
/// work. Throws as case_scene.
void check_cases(const StudyFile& study);

/// One line per SLAM option of the study (slam.settings or a slam.* axis) that belongs to a front
/// end none of its cases runs (`orbslam`'s vocabulary in an rgbdslam study), so it changes no
/// result: what `slam` and `compare` warn about for the same options, said before hours of work.
std::vector<std::string> unread_option_warnings(const StudyFile& study);

/// Columns of the results and timing tables for a level.
/// "status": in a study that runs an external system, the first metric column: "ok", or why the
/// run gave no evaluation (its metrics are then NULL).
inline constexpr const char* kStatusColumn = "status";
/// Whether any case of `study` runs an external system (interop/external_system.hpp).
bool runs_external_system(const StudyFile& study);
std::vector<std::string> metric_columns(const StudyFile& study);
std::vector<std::string> timing_columns(StudyLevel level);

/// The row of one SLAM-level run: its variant ("vanilla" or "wifi") and every metric and timing
/// column of its evaluation; a failed external run (`status` not "ok") has its status and NULL
/// numbers. A study that runs an external system has the status column first.
ResultRow slam_run_row(const StudyFile& study, bool wifi, const std::string& status,
                       const eval::RunEvaluation& evaluation, const std::string& scene_hash);

/// The rows of one case (no database involved).
std::vector<ResultRow> run_case(const StudyFile& study, const StudyCase& c,
                                const std::filesystem::path& scratch_dir, int jobs);

StudyRunSummary run_study(const StudyFile& study, const StudyRunOptions& options);

/// "i/N" (0 <= i < N, up to six digits each) as (i, N); ParseError naming --shard otherwise.
std::pair<int, int> parse_shard(const std::string& text);

}  // namespace wifislam::study
