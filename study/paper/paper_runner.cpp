#include "study/paper/paper_runner.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/dataset_recording.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "core/stop_signal.hpp"
#include "core/wall_clock.hpp"
#include "eval/evaluate_run.hpp"
#include "eval/report_writer.hpp"
#include "sim/generate/generation_pipeline.hpp"
#include "sim/scene/scene_loader.hpp"
#include "slam/bow/shipped_vocabulary.hpp"
#include "slam/place/fabmap_training.hpp"
#include "study/localisation_data.hpp"
#include "study/localisation_methods.hpp"
#include "study/localisation_report.hpp"
#include "study/paper/paper_folder.hpp"
#include "study/radio_resolution.hpp"
#include "study/recorded_dataset.hpp"
#include "study/result_store.hpp"
#include "study/study_runner.hpp"

namespace wifislam::study::paper {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

/// Writes `text` into `file` when it is missing; refuses a file that differs (the folder was
/// made with other settings or another build's twins).
void write_or_check(const fs::path& file, const std::string& text, const std::string& what) {
  std::error_code ec;
  if (!fs::exists(file, ec)) {
    write_file_atomic(file, text);
    return;
  }
  if (read_text(file) != text) {
    throw InvalidInputError(fmt::format(
        "{}: differs from this build's {}; the results beside it were made with it. Continue it "
        "with the build that made it, or give another folder (or --force to start over)",
        file.string(), what));
  }
}

nlohmann::json identity_json(const PaperSettings& settings) {
  return {{"format", folder::kFormatName}, {"format_version", 1}, {"fps", settings.fps}};
}

/// The runs of one study case: vanilla and Wi-Fi, evaluated as each ends.
struct CaseRuns {
  const StudyFile* study = nullptr;
  ResultStore* store = nullptr;
  StudyCase study_case;
  std::string scene_hash;
  std::map<bool, eval::RunEvaluation> evaluations;  // by wifi
};

/// The setting part of a run's folder name ("min_matches-50_inlier_distance-3").
std::string setting_folder(const StudyFile& study, const StudyCase& c) {
  std::string out;
  for (std::size_t a = 0; a < study.axes.size(); ++a) {
    std::string key = study.axes[a].key.substr(5);  // "slam."
    out += (out.empty() ? "" : "_") + key + "-" + c.values[a];
  }
  return out.empty() ? "defaults" : out;
}

/// Whether a run's folder is kept for the report's figures: the first seed's runs the paper
/// draws (RGBD-SLAM's bad maps and its 50/70 comparison, RTAB-Map's maps at 70 ms).
bool kept_for_figures(const PlannedStudy& planned, const std::string& setting, bool wifi) {
  if (planned.seed != twin_scene(planned.twin).seed) return false;
  switch (planned.experiment->part) {
    case Part::kRgbdslam:
      return setting == "min_matches-50_inlier_distance-3" ||
             setting == "min_matches-70_inlier_distance-3" ||
             (!wifi && (setting == "min_matches-100_inlier_distance-2" ||
                        setting == "min_matches-150_inlier_distance-2"));
    case Part::kRtabmap:
      return setting == "time_threshold_ms-70";
    default:
      return false;
  }
}

/// Adds this run's part times to timing.json (under a lock: shards share the folder).
void add_part_times(const fs::path& dir, const std::map<std::string, double>& seconds) {
  if (seconds.empty()) return;
  const fs::path lock_path = dir / (std::string(folder::kTiming) + ".lock");
  const int fd = ::open(lock_path.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
  if (fd >= 0) ::flock(fd, LOCK_EX);
  nlohmann::json timing = nlohmann::json::object();
  if (fs::exists(dir / folder::kTiming)) {
    timing = nlohmann::json::parse(read_text(dir / folder::kTiming), nullptr, false);
    if (!timing.is_object()) timing = nlohmann::json::object();
  }
  for (const auto& [part, s] : seconds) {
    const double before = timing.value(part, 0.0);
    timing[part] = before + s;
  }
  write_file_atomic(dir / folder::kTiming, timing.dump(1) + "\n");
  if (fd >= 0) ::close(fd);
}

class GroupRunner {
 public:
  GroupRunner(const PaperRunOptions& options, std::vector<PlannedStudy> studies)
      : options_(options), planned_(std::move(studies)) {}

  /// Runs the group's unfinished cases; returns the runs made.
  std::int64_t run(PaperRunSummary& summary, std::map<std::string, double>& times) {
    const fs::path dir = options_.folder;
    std::vector<StudyFile> files;
    std::vector<std::unique_ptr<ResultStore>> stores;
    std::vector<std::vector<StudyCase>> todo;
    for (const PlannedStudy& p : planned_) {
      files.push_back(load_study_file(dir / folder::kStudies / (p.name() + ".yaml")));
    }
    std::size_t cases = 0;
    for (std::size_t s = 0; s < files.size(); ++s) {
      stores.push_back(std::make_unique<ResultStore>(
          dir / folder::kResults / (planned_[s].name() + ".sqlite"), files[s],
          metric_columns(files[s]), timing_columns(files[s].level)));
      const std::set<std::string> finished = stores.back()->finished_cases();
      todo.emplace_back();
      for (const StudyCase& c : files[s].cases) {
        if (finished.count(c.id)) {
          ++summary.cases_skipped;
        } else {
          todo.back().push_back(c);
        }
      }
      cases += todo.back().size();
    }
    if (cases == 0) return 0;

    const PlannedStudy& any = planned_.front();
    const std::string group = folder::twin_seed(any.twin, any.seed);
    const fs::path work = dir / folder::kWork / group;
    fresh_work_folder(work);
    try {
      return run_in(work, group, files, stores, todo, cases, times);
    } catch (const StoppedBySignal&) {
      // Ctrl-C, or Slurm's scancel: the group's scratch folder (the twin's rendering, hundreds of
      // MB) goes, as `study run`'s case folder does; the cases stored so far stay for a rerun.
      remove_folder_marker_last(work, kOutputMarkerFile);
      throw;
    }
  }

 private:
  std::int64_t run_in(const fs::path& work, const std::string& group,
                      const std::vector<StudyFile>& files,
                      std::vector<std::unique_ptr<ResultStore>>& stores,
                      const std::vector<std::vector<StudyCase>>& todo, std::size_t cases,
                      std::map<std::string, double>& times) {
    // One scene for the whole group: every study of it sets only the seed on the same twin.
    std::size_t first = 0;
    while (todo[first].empty()) ++first;
    const sim::scene::Scene scene = case_scene(files[first], todo[first].front());
    const std::string scene_hash = sha256_hex(sim::scene::resolved_scene_yaml(scene));
    sim::generate::GenerateOptions overrides;
    overrides.fps = options_.settings.fps;
    const auto site =
        std::make_shared<const sim::site::Site>(sim::generate::resolve_scene(scene, overrides));

    std::vector<slam::feature::FeatureOptions> features;
    for (std::size_t s = 0; s < files.size(); ++s)
      for (const StudyCase& c : todo[s])
        features.push_back(case_slam_options(files[s], c).features);

    const auto start = Clock::now();
    sim::generate::GenerateOptions generate;
    generate.camera = sim::generate::CameraOutput::kDepthOnly;  // the evaluation reads depth; the
                                                                // runs replay features
    generate.on_progress = [](const sim::generate::GenerateProgress&) {
      throw_if_stop_requested();
    };
    const RecordedDataset dataset(site, work / "dataset", generate, features, options_.jobs);
    times["shared rendering and feature extraction"] += seconds_since(start);
    write_dataset_facts(site, dataset.summary(), group);
    progress(fmt::format("{}: generated and recorded {} frames ({:.0f} s); {} cases to run", group,
                         dataset.summary().frames, seconds_since(start), cases));

    std::int64_t runs = 0;
    for (std::size_t s = 0; s < files.size(); ++s) {
      if (todo[s].empty()) continue;
      const auto part_start = Clock::now();
      runs += run_study(planned_[s], files[s], *stores[s], todo[s], scene_hash, dataset, work);
      times[to_string(planned_[s].experiment->part)] += seconds_since(part_start);
    }
    remove_folder_marker_last(work,
                              kOutputMarkerFile);  // marker last: a cut-short removal stays ours
    return runs;
  }

  void progress(const std::string& line) {
    if (options_.on_progress) options_.on_progress(line);
  }

  static void fresh_work_folder(const fs::path& work) {
    if (fs::exists(work)) {
      if (!has_output_marker(work)) {
        throw InvalidInputError(
            fmt::format("{}: exists and was not made by wifislam (no {}); move it away",
                        work.string(), kOutputMarkerFile));
      }
      if (const std::string failed = remove_folder_marker_last(work, kOutputMarkerFile);
          !failed.empty()) {
        throw IoError(work.string() + ": left by an interrupted run, and it cannot be removed (" +
                      failed + ")");
      }
    }
    fs::create_directories(work);
    write_file_atomic(work / kOutputMarkerFile, "paper scratch folder\n");
  }

  /// What the twin's dataset held, and what its Wi-Fi can tell apart along the route
  /// (radio_resolution.hpp: the pauses' signatures against their true distances, the SLAM's
  /// similarity threshold): the measured side of the paper's cluster counts.
  void write_dataset_facts(const std::shared_ptr<const sim::site::Site>& site,
                           const sim::generate::GenerateSummary& g, const std::string& group) {
    const slam::wifi::WifiOptions wifi;
    const RadioResolution radio = radio_resolution(simulate_pauses(site, wifi), wifi);
    nlohmann::json facts = {
        {"twin", site->scene().name},
        {"seed", g.seed},
        {"fps", g.fps},
        {"frames", g.frames},
        {"duration_s", (g.last_time.ns - g.first_time.ns) / 1e9},
        {"pauses", g.pauses},
        {"wifi_scans", g.wifi_scans},
        {"access_points", g.access_points},
        {"aps_heard_per_pause_mean", g.aps_heard_per_pause_mean},
        {"wifi_similarity", wifi.similarity},
        {"near_similar_share", radio.near_similar_share},
        {"far_similar_share", radio.far_similar_share},
        {"radio_clusters", radio.clusters},
        {"resolution_m", radio.resolution_m ? nlohmann::json(*radio.resolution_m) : nullptr},
    };
    write_file_atomic(options_.folder / folder::kDatasets / (group + ".json"),
                      facts.dump(1) + "\n");
  }

  std::int64_t run_study(const PlannedStudy& planned, const StudyFile& file, ResultStore& store,
                         const std::vector<StudyCase>& todo, const std::string& scene_hash,
                         const RecordedDataset& dataset, const fs::path& work) {
    std::vector<CaseRuns> cases(todo.size());
    std::vector<StreamedRun> runs;
    std::vector<std::pair<std::size_t, bool>> owner;  // per run: its case and variant
    for (std::size_t i = 0; i < todo.size(); ++i) {
      cases[i] = {&file, &store, todo[i], scene_hash, {}};
      const slam::SlamOptions base = case_slam_options(file, todo[i]);
      for (bool wifi : {false, true}) {
        StreamedRun run;
        run.slam = base;
        run.slam.seed = dataset.summary().seed;  // as compare: the dataset's seed
        run.slam.wifi.enabled = wifi;
        slam::validate(run.slam);
        run.run_dir =
            work / planned.name() / setting_folder(file, todo[i]) / (wifi ? "wifi" : "vanilla");
        run.run_info = {
            {"input", dataset_run_input("dataset", recording_of_dataset(dataset.dataset_dir()))}};
        runs.push_back(std::move(run));
        owner.emplace_back(i, wifi);
      }
    }
    std::mutex mutex;
    run_recorded(dataset, runs, options_.jobs, [&](std::size_t r) {
      const auto [i, wifi] = owner[r];
      const StreamedRun& run = runs[r];
      eval::RunEvaluation evaluation =
          eval::evaluate_run(run.run_dir, dataset.dataset_dir(), eval::EvalOptions{});
      const std::string setting = setting_folder(file, todo[i]);
      if (kept_for_figures(planned, setting, wifi))
        keep_for_figures(planned, run, evaluation, setting, wifi);
      std::lock_guard lock(mutex);
      progress(fmt::format("{} {} {}: ATE {:.3f} m, loop closures {} ({} wrong place), {:.0f} s",
                           planned.name(), setting, wifi ? "wifi" : "vanilla",
                           evaluation.ate_rmse_m, evaluation.loop_closures_detected,
                           evaluation.loop_closure_score.online.wrong_place, run.summary.wall_s));
      CaseRuns& c = cases[i];
      c.evaluations[wifi] = std::move(evaluation);
      if (c.evaluations.size() == 2) {
        std::vector<ResultRow> rows;
        for (bool w : {false, true})
          rows.push_back(slam_run_row(file, w, "ok", c.evaluations[w], c.scene_hash));
        store.write_case(c.study_case, rows);
        c.evaluations.clear();
      }
      std::error_code ec;
      fs::remove_all(run.run_dir, ec);
    });
    return static_cast<std::int64_t>(runs.size());
  }

  void keep_for_figures(const PlannedStudy& planned, const StreamedRun& run,
                        const eval::RunEvaluation& evaluation, const std::string& setting,
                        bool wifi) {
    const fs::path kept =
        options_.folder / folder::kRuns / planned.name() / setting / (wifi ? "wifi" : "vanilla");
    std::error_code ec;
    fs::remove_all(kept, ec);
    fs::create_directories(kept);
    for (const char* name : {"trajectory.txt", "run.json", "loop_closures.csv"}) {
      if (fs::exists(run.run_dir / name)) fs::copy_file(run.run_dir / name, kept / name);
    }
    eval::write_evaluation(kept / "eval", evaluation, /*plots=*/true,
                           {&site_for_figures(planned)->world().plan, ""});
  }

  std::shared_ptr<const sim::site::Site> site_for_figures(const PlannedStudy& planned) {
    std::lock_guard lock(site_mutex_);
    if (!figure_site_) {
      sim::scene::Scene scene = twin_scene(planned.twin);
      scene.seed = planned.seed;
      sim::generate::GenerateOptions overrides;
      overrides.fps = options_.settings.fps;
      figure_site_ =
          std::make_shared<const sim::site::Site>(sim::generate::resolve_scene(scene, overrides));
    }
    return figure_site_;
  }

  const PaperRunOptions& options_;
  std::vector<PlannedStudy> planned_;
  std::mutex site_mutex_;
  std::shared_ptr<const sim::site::Site> figure_site_;
};

/// FAB-MAP, Wi-Fi FAB-MAP and ours on one twin and seed (`wifislam localize`'s defaults and
/// files); skipped when its folder exists.
bool run_localisation_part(const PaperRunOptions& options, const std::string& twin,
                           std::uint64_t seed) {
  const fs::path out = options.folder / folder::kLocalize / folder::twin_seed(twin, seed);
  if (fs::exists(out)) return false;
  LocalisationOptions localisation;
  LocalisationDataOptions data_options;
  data_options.seed = seed;
  data_options.wifi = localisation.wifi;
  const LocalisationData data = localisation_data_from_scene(twin_scene(twin), data_options);
  const auto vocabulary = slam::bow::load_vocabulary("");
  const slam::place::FabMapTraining training =
      slam::place::FabMapTraining::load(slam::place::shipped_fabmap_training_path());
  const LocalisationResult result = run_localisation(data, *vocabulary, training, localisation);
  AtomicDirectory dir(out, /*overwrite=*/false);
  write_localisation_report(dir.staging_path(), result, data, localisation);
  dir.commit();
  return true;
}

}  // namespace

void prepare_paper_folder(const PaperRunOptions& options) {
  const fs::path& dir = options.folder;
  if (options.seeds < 1) throw InvalidInputError("paper: --seeds must be >= 1");
  if (options.jobs < 1) throw InvalidInputError("paper: --jobs must be >= 1");
  const bool exists = fs::exists(dir);
  if (exists && options.force) {
    // Replaced in place, below: <dir>.partial and <dir>.replaced are not this command's.
    OutputFolderRequest request(dir, /*force=*/true, {}, {});
    request.staged_beside = false;
    check_output_folder(request);
    // --force starts a paper folder over; any other folder of ours (a dataset, a run) is not
    // one to replace here, whatever its marker says.
    if (fs::is_directory(dir) && !fs::is_empty(dir) && !fs::exists(dir / folder::kIdentity)) {
      throw InvalidInputError(fmt::format(
          "{}: not a paper folder (no {}); --force replaces only a folder `wifislam paper` made",
          dir.string(), folder::kIdentity));
    }
    // Nor one a `paper` run is working in: its studies hold their databases' locks.
    if (fs::is_directory(dir / folder::kResults)) {
      for (const fs::directory_entry& entry : fs::directory_iterator(dir / folder::kResults)) {
        const fs::path& db = entry.path();
        if (db.extension() == ".sqlite" && DatabaseLock::is_held(db)) {
          throw InvalidInputError(fmt::format(
              "{}: a `paper` run is working in it now ({} is being written); --force replaces "
              "it once that run is done",
              dir.string(), db.string()));
        }
      }
    }
    fs::remove_all(dir);
  }
  if (!fs::exists(dir)) {
    fs::create_directories(dir);
    write_file_atomic(dir / kOutputMarkerFile,
                      "Written by wifislam paper. A second `paper` run continues it; --force "
                      "replaces it.\n");
  } else {
    if (!fs::is_directory(dir)) {
      throw InvalidInputError(dir.string() + ": exists and is not a folder");
    }
    const bool empty = fs::is_empty(dir);
    if (!empty && !fs::exists(dir / folder::kIdentity)) {
      throw InvalidInputError(fmt::format(
          "{}: exists and is not a paper folder (no {}); give a new or empty folder, or one "
          "`wifislam paper` made",
          dir.string(), folder::kIdentity));
    }
    if (empty) write_file_atomic(dir / kOutputMarkerFile, "Written by wifislam paper.\n");
  }
  const std::string identity = identity_json(options.settings).dump(1) + "\n";
  if (fs::exists(dir / folder::kIdentity) && read_text(dir / folder::kIdentity) != identity) {
    const nlohmann::json old =
        nlohmann::json::parse(read_text(dir / folder::kIdentity), nullptr, false);
    throw InvalidInputError(fmt::format(
        "{}: made with {}, not {}; continue it with the same settings or give another folder",
        dir.string(), old.is_object() ? fmt::format("--fps {}", old.value("fps", 0.0)) : "?",
        fmt::format("--fps {}", options.settings.fps)));
  }
  write_or_check(dir / folder::kIdentity, identity, "paper settings");
  for (const char* sub : {folder::kScenes, folder::kStudies, folder::kResults, folder::kDatasets,
                          folder::kLocalize, folder::kRuns, folder::kFigures}) {
    fs::create_directories(dir / sub);
  }
  for (const std::string& twin : options.twins) {
    write_or_check(dir / folder::kScenes / (twin + ".yaml"), twin_scene_yaml(twin),
                   twin + " twin (scenes/" + twin + ".yaml)");
  }
  for (const PlannedStudy& s : planned_studies(options.parts, options.twins, options.seeds)) {
    write_or_check(dir / folder::kStudies / (s.name() + ".yaml"),
                   study_file_text(s, options.settings), "study file");
  }
}

PaperRunSummary run_paper(const PaperRunOptions& options) {
  const auto start = Clock::now();
  if (options.shard_count < 1 || options.shard_index < 0 ||
      options.shard_index >= options.shard_count) {
    throw InvalidInputError(fmt::format("--shard {}/{}: expected i/N with 0 <= i < N",
                                        options.shard_index, options.shard_count));
  }
  prepare_paper_folder(options);
  PaperRunSummary summary;
  // Groups: one twin and seed, in plan order.
  std::vector<std::vector<PlannedStudy>> groups;
  std::vector<std::pair<std::string, std::uint64_t>> group_keys;
  for (int k = 0; k < options.seeds; ++k) {
    for (const std::string& twin : twin_names()) {
      if (std::find(options.twins.begin(), options.twins.end(), twin) == options.twins.end())
        continue;
      const std::uint64_t seed = twin_scene(twin).seed + static_cast<std::uint64_t>(k);
      group_keys.emplace_back(twin, seed);
      groups.emplace_back();
      for (const PlannedStudy& s : planned_studies(options.parts, {twin}, k + 1)) {
        if (s.seed == seed) groups.back().push_back(s);
      }
    }
  }
  const bool with_fabmap =
      std::find(options.parts.begin(), options.parts.end(), Part::kFabmap) != options.parts.end();
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (static_cast<int>(g % static_cast<std::size_t>(options.shard_count)) !=
        options.shard_index) {
      continue;
    }
    std::map<std::string, double> times;
    if (!groups[g].empty()) {
      GroupRunner runner(options, groups[g]);
      summary.runs += runner.run(summary, times);
    }
    if (with_fabmap) {
      const auto fabmap_start = Clock::now();
      if (run_localisation_part(options, group_keys[g].first, group_keys[g].second)) {
        ++summary.localisations;
        times["fabmap"] += seconds_since(fabmap_start);
        if (options.on_progress) {
          options.on_progress(
              fmt::format("fabmap {}: localised ({:.0f} s)",
                          folder::twin_seed(group_keys[g].first, group_keys[g].second),
                          seconds_since(fabmap_start)));
        }
      }
    }
    add_part_times(options.folder, times);
  }
  std::error_code ec;
  fs::remove(options.folder / folder::kWork, ec);  // empty once every group is done
  summary.wall_s = seconds_since(start);
  return summary;
}

std::map<std::string, double> paper_part_times(const fs::path& dir) {
  std::map<std::string, double> out;
  if (!fs::exists(dir / folder::kTiming)) return out;
  const nlohmann::json timing =
      nlohmann::json::parse(read_text(dir / folder::kTiming), nullptr, false);
  if (!timing.is_object()) return out;
  for (const auto& [k, v] : timing.items())
    if (v.is_number()) out[k] = v.get<double>();
  return out;
}

}  // namespace wifislam::study::paper
