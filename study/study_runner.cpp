#include "study/study_runner.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <mutex>
#include <regex>
#include <set>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/output_folder.hpp"
#include "core/stop_signal.hpp"
#include "core/wall_clock.hpp"
#include "core/worker_pool.hpp"
#include "core/yaml_document.hpp"
#include "interop/external_system.hpp"
#include "sim/scene/scene_keys.hpp"
#include "sim/scene/scene_loader.hpp"
#include "study/comparison_study.hpp"
#include "study/front_end_choice.hpp"
#include "study/radio_resolution.hpp"
#include "study/result_columns.hpp"
#include "study/site_cache.hpp"

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

}  // namespace

sim::scene::Scene case_scene(const StudyFile& study, const StudyCase& c) {
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
    try {
      for (const auto& [key, value] : study.scene_set)
        sim::scene::set_scene_key(root, key, YAML::Load(value));
      for (std::size_t a = 0; a < study.axes.size(); ++a) {
        if (study.axes[a].kind != AxisKind::kSceneKey) continue;
        sim::scene::set_scene_key(root, study.axes[a].key, YAML::Load(c.values[a]));
      }
    } catch (const InvalidInputError& e) {
      // A key the scene has no place for ("corridors[9]" of four): named without the study file.
      throw ParseError(study.path.string(), "case " + c.id,
                       fmt::format("{}: {}", case_label(study, c), e.what()));
    }
    YAML::Emitter out;
    out << root;
    return sim::scene::load_scene_yaml(out.c_str(), source);
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
      if (axis.kind == AxisKind::kFrontend || axis.kind == AxisKind::kSystem) {
        o.frontend = axis_front_end(study, axis.kind, c.values[a]);
      }
    }
    slam::validate(o);
  } catch (const Error& e) {
    throw ParseError(study.path.string(), "case " + c.id,
                     fmt::format("{}: {}", case_label(study, c), e.what()));
  }
  return o;
}

std::vector<std::string> unread_option_warnings(const StudyFile& study) {
  if (study.level != StudyLevel::kSlam) return {};  // the radio level refuses them when read
  std::vector<std::string> keys;
  for (const std::string& s : study.slam.settings) keys.push_back(s.substr(0, s.find('=')));
  for (const StudyAxis& axis : study.axes)
    if (axis.kind == AxisKind::kSlamOption) keys.push_back(axis.key.substr(5));
  std::vector<std::string> frontends;
  for (const StudyCase& c : study.cases) {
    const std::string frontend = case_slam_options(study, c).frontend;
    if (std::find(frontends.begin(), frontends.end(), frontend) == frontends.end())
      frontends.push_back(frontend);
  }
  std::vector<std::string> out;
  for (const std::string& w : slam::unread_option_warnings(keys, frontends))
    out.push_back(study.path.string() + ": " + w);
  return out;
}

void check_cases(const StudyFile& study) {
  std::set<std::string> vocabularies;
  for (const StudyCase& c : study.cases) {
    (void)case_scene(study, c);
    const slam::SlamOptions options = case_slam_options(study, c);
    if (!options.orbslam.vocabulary.empty()) vocabularies.insert(options.orbslam.vocabulary);
  }
  // A vocabulary file that is not there failed the first ORB-SLAM case, after the database and
  // its scratch folder were made (and `study cases` had said every case checks).
  for (const std::string& v : vocabularies) {
    require_input_file(
        v, fmt::format("the vocabulary file of study '{}' (slam.vocabulary)", study.name));
  }
}

bool runs_external_system(const StudyFile& study) {
  if (interop::is_external_frontend(study.slam.frontend)) return true;
  for (const StudyAxis& axis : study.axes) {
    for (const std::string& v : axis.values) {
      if ((axis.kind == AxisKind::kFrontend || axis.kind == AxisKind::kSystem) &&
          interop::is_external_frontend(axis.kind == AxisKind::kSystem ? system_front_end(v) : v)) {
        return true;
      }
    }
  }
  return false;
}

std::vector<std::string> metric_columns(const StudyFile& study) {
  if (study.level == StudyLevel::kRadio) return column_names(radio_metric_columns());
  std::vector<std::string> columns = column_names(slam_metric_columns());
  // A study of external systems says per row whether the run gave an evaluation; the studies of
  // our front ends keep their schema.
  if (runs_external_system(study)) columns.insert(columns.begin(), kStatusColumn);
  return columns;
}

std::vector<std::string> timing_columns(StudyLevel level) {
  if (level == StudyLevel::kRadio) return {"case_s"};
  return column_names(slam_timing_columns());
}

namespace {

/// A SLAM case's scratch folder, `scratch_dir`/<case id>, empty. A previous attempt at this case,
/// killed before its rows were written, left its folder: it is removed, but only when it carries
/// this tool's marker (never a same-named folder of the user's).
fs::path fresh_case_folder(const fs::path& scratch_dir, const StudyCase& c) {
  const fs::path work = scratch_dir / c.id;
  if (fs::exists(work)) {
    if (!fs::exists(work / kOutputMarkerFile) && !fs::is_empty(work)) {
      throw InvalidInputError(
          fmt::format("{}: exists and was not made by wifislam (no {} in it); move it away",
                      work.string(), kOutputMarkerFile));
    }
    if (const std::string failed = remove_folder_marker_last(work, kOutputMarkerFile);
        !failed.empty()) {
      throw IoError(work.string() +
                    ": left by an earlier attempt at this case, and it cannot be "
                    "removed (" +
                    failed + ")");
    }
  }
  fs::create_directories(work);
  write_file_atomic(work / kOutputMarkerFile, "study case scratch folder\n");
  return work;
}

/// The comparison of one SLAM-level case: its scene and options, one seed, vanilla and Wi-Fi.
ComparisonOptions case_comparison(const StudyFile& study, const StudyCase& c,
                                  const slam::SlamOptions& slam_options, int jobs) {
  ComparisonOptions compare;
  compare.slam = slam_options;
  // The labels of the runs' folders: the options set, as the study file gives them.
  for (const std::string& s : study.slam.settings) compare.settings.push_back(s);
  for (std::size_t a = 0; a < study.axes.size(); ++a) {
    if (study.axes[a].kind == AxisKind::kSlamOption) {
      compare.settings.push_back(study.axes[a].key.substr(5) + "=" + c.values[a]);
    }
  }
  compare.slam_seed_set = assigns_slam_seed(compare.settings);
  compare.seeds = 1;
  compare.fps = study.slam.fps;
  compare.max_frames = study.slam.max_frames;
  compare.plots = false;
  compare.jobs = jobs;
  compare.dataset_colour = false;  // the case's folder is deleted: depth for the evaluation only
  return compare;
}

}  // namespace

ResultRow slam_run_row(const StudyFile& study, bool wifi, const std::string& status,
                       const eval::RunEvaluation& evaluation, const std::string& scene_hash) {
  ResultRow row;
  row.variant = wifi ? "wifi" : "vanilla";
  row.scene_hash = scene_hash;
  row.metrics = column_values(slam_metric_columns(), evaluation);
  row.timing = column_values(slam_timing_columns(), evaluation);
  if (status != "ok") {  // a failed external run: its status, and no numbers (NULL)
    for (auto* columns : {&row.metrics, &row.timing})
      for (ResultColumn& column : *columns) column.value = SqlValue();
  }
  if (runs_external_system(study)) row.metrics.insert(row.metrics.begin(), {kStatusColumn, status});
  return row;
}

std::vector<ResultRow> run_case(const StudyFile& study, const StudyCase& c,
                                const fs::path& scratch_dir, int jobs) {
  const auto start = Clock::now();
  const sim::scene::Scene scene = case_scene(study, c);
  const slam::SlamOptions slam_options = case_slam_options(study, c);
  const std::string scene_hash = sha256_hex(sim::scene::resolved_scene_yaml(scene));
  if (study.level == StudyLevel::kRadio) {
    const RadioResolution r =
        radio_resolution(simulate_pauses(shared_site(scene), slam_options.wifi), slam_options.wifi);
    ResultRow row;
    row.variant = "radio";
    row.scene_hash = scene_hash;
    row.metrics = column_values(radio_metric_columns(), r);
    row.timing = {{"case_s", seconds_since(start)}};
    return {row};
  }
  const fs::path work = fresh_case_folder(scratch_dir, c);
  ComparisonResult result;
  try {
    result = run_comparison({scene}, case_comparison(study, c, slam_options, jobs), work);
  } catch (const StoppedBySignal&) {
    // Stopped under `study run`'s guard (Ctrl-C, or Slurm's SIGTERM): the case is not finished
    // and a rerun starts it over, so its datasets and runs go now. After any other error they
    // stay to be looked at, until the rerun replaces them.
    // Marker last: a removal cut short (a second Ctrl-C) leaves a folder still known as ours.
    remove_folder_marker_last(work, kOutputMarkerFile);
    std::error_code ec;
    fs::remove(scratch_dir, ec);  // only when empty: other shards' cases may be in it
    throw;
  }
  std::vector<ResultRow> rows;
  for (const ComparisonCase& run : result.cases)
    rows.push_back(slam_run_row(study, run.wifi, run.status, run.evaluation, scene_hash));
  remove_folder_marker_last(work, kOutputMarkerFile);
  return rows;
}

std::pair<int, int> parse_shard(const std::string& text) {
  static const std::regex form(R"(^([0-9]{1,6})/([0-9]{1,6})$)");
  std::smatch m;
  if (!std::regex_match(text, m, form)) throw ParseError("--shard", text, "expected i/N, e.g. 0/4");
  const int i = std::stoi(m[1]), n = std::stoi(m[2]);
  if (n < 1 || i >= n) throw ParseError("--shard", text, "expected 0 <= i < N");
  return {i, n};
}

StudyRunSummary run_study(const StudyFile& study, const StudyRunOptions& options) {
  const auto start = Clock::now();
  if (options.shard_count < 1 || options.shard_index < 0 ||
      options.shard_index >= options.shard_count) {
    throw InvalidInputError(fmt::format("--shard {}/{}: expected i/N with 0 <= i < N",
                                        options.shard_index, options.shard_count));
  }
  check_cases(study);  // every value, before any work
  const fs::path scratch = options.database.string() + ".work";
  if (std::error_code ec; study.level == StudyLevel::kSlam && fs::exists(scratch, ec) &&
                          !fs::is_directory(scratch, ec)) {
    // The SLAM cases' scratch folder goes there: say so now, not as an internal error later.
    throw InvalidInputError(fmt::format(
        "{}: a file where this database's scratch folder for its cases goes; move it away",
        scratch.string()));
  }
  ResultStore store(options.database, study, metric_columns(study), timing_columns(study.level),
                    options.replace_database);
  const std::vector<StudyCase> cases = shard_cases(study, options.shard_index, options.shard_count);
  const std::set<std::string> finished = store.finished_cases();
  // A resumed case's rows must be of the scene it would run now: an edited scene file (between
  // shards, or before a rerun) would mix two versions of it in one table without a word.
  const std::map<std::string, std::string> hashes = store.finished_scene_hashes();
  for (const StudyCase& c : cases) {
    const auto it = hashes.find(c.id);
    if (it == hashes.end() || it->second.empty()) continue;
    if (it->second != sha256_hex(sim::scene::resolved_scene_yaml(case_scene(study, c)))) {
      throw InvalidInputError(fmt::format(
          "{}: case {} was run on another version of its scene: {} has changed since its rows "
          "were written; write to a new database (-o)",
          options.database.string(), c.id, study.scene_path.string()));
    }
  }
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

  std::mutex mutex;  // the store and the progress line
  std::size_t done = 0;
  // Radio cases run `jobs` at a time; a SLAM case runs its two variants in parallel instead.
  const int case_threads = study.level == StudyLevel::kRadio ? options.jobs : 1;
  const int slam_jobs = study.level == StudyLevel::kSlam ? options.jobs : 1;
  parallel_for(clamp_thread_count(case_threads), todo.size(), [&](std::size_t i) {
    throw_if_stop_requested();  // between cases; a SLAM case also stops at its next frame
    const auto case_start = Clock::now();
    if (study.level == StudyLevel::kSlam) {
      // A SLAM case takes minutes: say which one is under way, not only when it ends.
      std::lock_guard lock(mutex);
      progress(fmt::format("[{}/{}] case {} ({}): started", summary.skipped + done + 1,
                           cases.size(), todo[i].id, case_label(study, todo[i])));
    }
    const std::vector<ResultRow> rows = run_case(study, todo[i], scratch, slam_jobs);
    // A stop that came while the case ran, wherever it was noticed (or not), keeps the case out
    // of the database: rows of a run cut short must never read as a finished case.
    throw_if_stop_requested();
    std::lock_guard lock(mutex);
    store.write_case(todo[i], rows);
    ++done;
    progress(fmt::format("[{}/{}] case {} ({}): {:.1f} s", summary.skipped + done, cases.size(),
                         todo[i].id, case_label(study, todo[i]), seconds_since(case_start)));
  });
  std::error_code ec;
  fs::remove(scratch, ec);  // empty once every case is done (never recursive: it may be shared)
  summary.ran = done;
  summary.wall_s = seconds_since(start);
  return summary;
}

}  // namespace wifislam::study
