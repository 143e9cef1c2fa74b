#include "study/study_runner.hpp"

#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "core/thread_start.hpp"
#include "core/yaml_document.hpp"
#include "sim/scene/scene_keys.hpp"
#include "sim/scene/scene_loader.hpp"
#include "study/comparison_study.hpp"
#include "study/radio_resolution.hpp"

namespace wifislam::study {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string case_label(const StudyFile& study, const StudyCase& c) {
  std::string label;
  for (std::size_t a = 0; a < study.axes.size(); ++a) {
    label += (a ? "; " : "") + study.axes[a].key + "=" + c.values[a];
  }
  return label;
}

/// The base scene's YAML, read once per study file.
const YAML::Node& base_scene_yaml(const StudyFile& study) {
  static std::mutex mutex;
  static std::map<std::string, YAML::Node> cache;
  std::lock_guard lock(mutex);
  const std::string key = study.scene_path.string();
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, load_yaml_file(key)).first;
  return it->second;
}

std::int64_t count(std::int64_t v) { return v; }

}  // namespace

sim::Scene case_scene(const StudyFile& study, const StudyCase& c) {
  YAML::Node root;
  {
    const YAML::Node& base = base_scene_yaml(study);
    static std::mutex clone_mutex;  // yaml-cpp nodes are not safe to read from two threads
    std::lock_guard lock(clone_mutex);
    root = YAML::Clone(base);
  }
  // Errors name the scene file, the case and its axis values, then the line and key.
  const std::string source = fmt::format("{} as case {} of {} ({})", study.scene_path.string(),
                                         c.id, study.path.string(), case_label(study, c));
  try {
    for (const auto& [key, value] : study.scene_set)
      sim::set_scene_key(root, key, YAML::Load(value));
    for (std::size_t a = 0; a < study.axes.size(); ++a) {
      if (study.axes[a].kind != AxisKind::kSceneKey) continue;
      sim::set_scene_key(root, study.axes[a].key, YAML::Load(c.values[a]));
    }
    YAML::Emitter out;
    out << root;
    return sim::load_scene_yaml(out.c_str(), source);
  } catch (const YAML::Exception& e) {
    throw ParseError(study.path.string(), "case " + c.id,
                     fmt::format("{}: {}", case_label(study, c), e.what()));
  }
}

slam::SlamOptions case_slam_options(const StudyFile& study, const StudyCase& c) {
  slam::SlamOptions o;
  o.frontend = study.slam.frontend;
  try {
    for (const std::string& s : study.slam.settings) slam::set_option_assignment(o, s);
    for (std::size_t a = 0; a < study.axes.size(); ++a) {
      const StudyAxis& axis = study.axes[a];
      if (axis.kind == AxisKind::kSlamOption) slam::set_option(o, axis.key.substr(5), c.values[a]);
      if (axis.kind == AxisKind::kFrontend) o.frontend = c.values[a];
    }
    slam::validate(o);
  } catch (const Error& e) {
    throw ParseError(study.path.string(), "case " + c.id,
                     fmt::format("{}: {}", case_label(study, c), e.what()));
  }
  return o;
}

void check_cases(const StudyFile& study) {
  for (const StudyCase& c : study.cases) {
    (void)case_scene(study, c);
    (void)case_slam_options(study, c);
  }
}

std::vector<std::string> metric_columns(StudyLevel level) {
  if (level == StudyLevel::kRadio) {
    return {"pauses",
            "pairs",
            "resolution_m",
            "near_similar_share",
            "far_similar_share",
            "clusters",
            "aps_heard_per_pause"};
  }
  return {"ate_rmse_m",
          "keyframes",
          "loop_closures",
          "scored_closures",
          "correct_closures",
          "right_place_imprecise",
          "wrong_place_closures",
          "far_wrong_place_closures",
          "false_positive_pct",
          "revisit_episodes",
          "false_negatives",
          "false_negative_pct",
          "wrong_place_after_pruning",
          "far_wrong_place_after_pruning",
          "false_negatives_after_pruning",
          "candidate_comparisons",
          "long_term_comparisons",
          "wifi_clusters",
          "cost_model_s"};
}

std::vector<std::string> timing_columns(StudyLevel level) {
  if (level == StudyLevel::kRadio) return {"case_s"};
  return {"loop_closure_detection_s", "bounded_module_s", "wifi_overhead_s", "total_s", "wall_s"};
}

std::vector<ResultRow> run_case(const StudyFile& study, const StudyCase& c,
                                const fs::path& scratch_dir, int jobs) {
  const auto start = Clock::now();
  const sim::Scene scene = case_scene(study, c);
  const slam::SlamOptions slam_options = case_slam_options(study, c);
  const std::string scene_hash = sha256_hex(sim::resolved_scene_yaml(scene));
  std::vector<ResultRow> rows;
  if (study.level == StudyLevel::kRadio) {
    const RadioResolution r =
        radio_resolution(simulate_pauses(scene, slam_options.wifi), slam_options.wifi);
    ResultRow row;
    row.variant = "radio";
    row.scene_hash = scene_hash;
    row.metrics = {{"pauses", std::int64_t{r.pauses}},
                   {"pairs", std::int64_t{r.pairs}},
                   {"resolution_m", r.resolution_m ? SqlValue(*r.resolution_m) : SqlValue()},
                   {"near_similar_share", r.near_similar_share},
                   {"far_similar_share", r.far_similar_share},
                   {"clusters", std::int64_t{r.clusters}},
                   {"aps_heard_per_pause", r.aps_heard_per_pause}};
    row.timing = {{"case_s", std::chrono::duration<double>(Clock::now() - start).count()}};
    rows.push_back(std::move(row));
    return rows;
  }

  ComparisonOptions compare;
  compare.frontend = slam_options.frontend;
  for (const std::string& s : study.slam.settings) compare.settings.push_back(s);
  for (std::size_t a = 0; a < study.axes.size(); ++a) {
    if (study.axes[a].kind == AxisKind::kSlamOption) {
      compare.settings.push_back(study.axes[a].key.substr(5) + "=" + c.values[a]);
    }
  }
  compare.seeds = 1;
  compare.fps = study.slam.fps;
  compare.max_frames = study.slam.max_frames;
  compare.plots = false;
  compare.jobs = jobs;
  const fs::path work = scratch_dir / c.id;
  // A previous attempt at this case, killed before its rows were written, left its folder: remove
  // it, but only when it carries this tool's marker (never a same-named folder of the user's).
  if (fs::exists(work)) {
    if (!fs::exists(work / kOutputMarkerFile) && !fs::is_empty(work)) {
      throw InvalidInputError(
          fmt::format("{}: exists and was not made by wifislam (no {} in it); move it away",
                      work.string(), kOutputMarkerFile));
    }
    fs::remove_all(work);
  }
  fs::create_directories(work);
  write_file_atomic(work / kOutputMarkerFile, "study case scratch folder\n");
  const ComparisonResult result = run_comparison({scene}, compare, work);
  for (const ComparisonCase& run : result.cases) {
    const eval::RunEvaluation& e = run.evaluation;
    const auto lt = e.timing.roles.find("long_term");
    const eval::RoleTiming long_term = lt == e.timing.roles.end() ? eval::RoleTiming{} : lt->second;
    const eval::LoopClosureCounts& on = e.loop_closure_score.online;
    const eval::LoopClosureCounts& pruned = e.loop_closure_score.after_pruning;
    ResultRow row;
    row.variant = run.wifi ? "wifi" : "vanilla";
    row.scene_hash = scene_hash;
    row.metrics = {{"ate_rmse_m", e.ate_rmse_m},
                   {"keyframes", count(e.keyframes)},
                   {"loop_closures", count(e.loop_closures_detected)},
                   {"scored_closures", count(on.scored)},
                   {"correct_closures", count(on.correct)},
                   {"right_place_imprecise", count(on.right_place_imprecise)},
                   {"wrong_place_closures", count(on.wrong_place)},
                   {"far_wrong_place_closures", count(on.far_wrong_place)},
                   {"false_positive_pct", on.false_positive_pct},
                   {"revisit_episodes", count(e.revisit_episodes)},
                   {"false_negatives", count(on.false_negatives)},
                   {"false_negative_pct", on.false_negative_pct},
                   {"wrong_place_after_pruning", count(pruned.wrong_place)},
                   {"far_wrong_place_after_pruning", count(pruned.far_wrong_place)},
                   {"false_negatives_after_pruning", count(pruned.false_negatives)},
                   {"candidate_comparisons", count(e.candidate_comparisons)},
                   {"long_term_comparisons", count(long_term.comparisons)},
                   {"wifi_clusters", count(e.wifi_clusters)},
                   {"cost_model_s", e.cost_model_s ? SqlValue(*e.cost_model_s) : SqlValue()}};
    row.timing = {
        {"loop_closure_detection_s", e.loop_closure_detection_s},
        {"bounded_module_s", e.timing.candidate_selection_s + long_term.time_s + e.optimisation_s},
        {"wifi_overhead_s", e.wifi_overhead_s},
        {"total_s", e.total_s},
        {"wall_s", e.wall_s}};
    rows.push_back(std::move(row));
  }
  fs::remove_all(work);
  return rows;
}

StudyRunSummary run_study(const StudyFile& study, const StudyRunOptions& options) {
  const auto start = Clock::now();
  if (options.shard_count < 1 || options.shard_index < 0 ||
      options.shard_index >= options.shard_count) {
    throw InvalidInputError(fmt::format("--shard {}/{}: expected i/N with 0 <= i < N",
                                        options.shard_index, options.shard_count));
  }
  check_cases(study);  // every value, before any work
  ResultStore store(options.database, study, metric_columns(study.level),
                    timing_columns(study.level));
  const std::vector<StudyCase> cases = shard_cases(study, options.shard_index, options.shard_count);
  const std::set<std::string> finished = store.finished_cases();
  std::vector<StudyCase> todo;
  for (const StudyCase& c : cases)
    if (!finished.count(c.id)) todo.push_back(c);

  StudyRunSummary summary;
  summary.cases = cases.size();
  summary.skipped = cases.size() - todo.size();
  const auto progress = [&](const std::string& line) {
    if (options.on_progress) options.on_progress(line);
  };
  if (summary.skipped > 0) {
    progress(fmt::format("{} of {} cases already in {}; running the other {}", summary.skipped,
                         cases.size(), options.database.string(), todo.size()));
  }
  const fs::path scratch = options.database.string() + ".work";

  std::mutex mutex;  // the store, the progress line and the first error
  std::exception_ptr first_error;
  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  // Radio cases run `jobs` at a time; a SLAM case runs its two variants in parallel instead.
  const int case_threads = study.level == StudyLevel::kRadio ? options.jobs : 1;
  const int slam_jobs = study.level == StudyLevel::kSlam ? options.jobs : 1;
  const auto worker = [&] {
    for (std::size_t i = next++; i < todo.size(); i = next++) {
      {
        std::lock_guard lock(mutex);
        if (first_error) return;
      }
      try {
        const auto case_start = Clock::now();
        const std::vector<ResultRow> rows = run_case(study, todo[i], scratch, slam_jobs);
        std::lock_guard lock(mutex);
        store.write_case(todo[i], rows);
        ++done;
        progress(fmt::format("[{}/{}] case {} ({}): {:.1f} s", summary.skipped + done, cases.size(),
                             todo[i].id, case_label(study, todo[i]),
                             std::chrono::duration<double>(Clock::now() - case_start).count()));
      } catch (...) {
        std::lock_guard lock(mutex);
        if (!first_error) first_error = std::current_exception();
      }
    }
  };
  const int threads =
      std::max(1, std::min<int>(clamp_thread_count(case_threads), static_cast<int>(todo.size())));
  std::vector<std::thread> pool;
  start_threads(pool, threads - 1, worker);
  worker();
  for (std::thread& t : pool) t.join();
  if (first_error) std::rethrow_exception(first_error);
  std::error_code ec;
  fs::remove(scratch, ec);  // empty once every case is done (never recursive: it may be shared)
  summary.ran = done;
  summary.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  return summary;
}

}  // namespace wifislam::study
