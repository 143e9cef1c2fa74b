#include "study/comparison_study.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <set>

#include <fmt/format.h>

#include "core/atomic_file.hpp"
#include "core/csv_field.hpp"
#include "core/dataset_recording.hpp"
#include "core/error.hpp"
#include "core/stop_signal.hpp"
#include "core/worker_pool.hpp"
#include "eval/evaluate_run.hpp"
#include "eval/report_writer.hpp"
#include "eval/run_divergence.hpp"
#include "interop/external_run.hpp"
#include "sim/generate/generation_pipeline.hpp"
#include "study/front_end_choice.hpp"
#include "study/streamed_runs.hpp"

namespace wifislam::study {

namespace {

using Setting = std::vector<std::pair<std::string, std::string>>;

/// The column label: every option that differs from the defaults, --set ones first.
std::string label_of(const std::vector<std::string>& base, const Setting& setting) {
  std::string out;
  for (const std::string& assignment : base) out += (out.empty() ? "" : " ") + assignment;
  for (const auto& [key, value] : setting) out += (out.empty() ? "" : " ") + key + "=" + value;
  return out.empty() ? "defaults" : out;
}

/// Longest run-folder name of a setting: well below the file systems' 255 bytes.
constexpr std::size_t kMaxSettingFolderBytes = 120;

/// Folder-name form of a label ("min_matches=10 inlier_distance=3" -> "min_matches-10_...";
/// "frontend=external:sys/a.yaml" -> "frontend-external-sys-a.yaml": one folder, no separator).
/// A long one keeps its start and ends with a hash of the whole label, so it stays unique.
std::string folder_of(const std::string& label) {
  std::string out;
  for (char c : label) out += c == '=' || c == ':' || c == '/' ? '-' : c == ' ' ? '_' : c;
  if (out.size() > kMaxSettingFolderBytes) {
    out = out.substr(0, kMaxSettingFolderBytes - 13) + "-" + sha256_hex(label).substr(0, 12);
  }
  return out;
}

std::vector<Setting> expand(const std::vector<SweepAxis>& sweeps) {
  std::vector<Setting> out = {{}};
  for (const SweepAxis& axis : sweeps) {
    std::vector<Setting> next;
    for (const Setting& partial : out) {
      for (const std::string& value : axis.values) {
        Setting s = partial;
        s.emplace_back(axis.key, value);
        next.push_back(std::move(s));
      }
    }
    out = std::move(next);
  }
  return out;
}

slam::SlamOptions options_for(const ComparisonOptions& options, const Setting& setting, bool wifi,
                              std::uint64_t seed) {
  slam::SlamOptions o = options.slam;
  if (!options.slam_seed_set) o.seed = seed;
  for (const auto& [key, value] : setting) slam::set_option(o, key, value);
  o.wifi.enabled = wifi;
  slam::validate(o);
  return o;
}

std::string csv_field(const nlohmann::ordered_json& value) {
  if (value.is_string()) return wifislam::csv_field(value.get<std::string>());
  if (value.is_null()) return "";
  return value.dump();
}

/// Metrics of one table cell: the cases of one scene, setting and variant (one per seed).
struct Cell {
  int runs = 0;
  std::vector<double> ate_rmse_m;  // one per seed: mean and spread
  double loop_closure_s = 0, wifi_overhead_s = 0, total_s = 0;
  /// The paper's time figure: the module bounding acts on (candidate selection, Wi-Fi
  /// clustering included, and the long-term candidates' verifications) plus optimisation.
  double bounded_module_s = 0;
  double cost_model_s = 0;  // the front end's deterministic time, when it has one
  bool has_cost_model = false;
  /// RTAB-Map's loop-closure detection time (likelihood + posterior + loop hypothesis
  /// verification), measured and by the cost model, when the front end reports it.
  double rtabmap_loop_closure_s = 0, rtabmap_loop_closure_cost_s = 0;
  bool has_rtabmap_loop_closure = false;
  std::int64_t episodes = 0;
  eval::LoopClosureCounts online, pruned;  // summed over seeds (percentages not used)
  std::int64_t comparisons = 0, long_term_comparisons = 0, keyframes = 0;

  void add(const eval::RunEvaluation& e) {
    ++runs;
    const auto long_term = e.timing.roles.find("long_term");
    const eval::RoleTiming lt =
        long_term == e.timing.roles.end() ? eval::RoleTiming{} : long_term->second;
    long_term_comparisons += lt.comparisons;
    for (auto [sum, one] : {std::pair{&online, &e.loop_closure_score.online},
                            std::pair{&pruned, &e.loop_closure_score.after_pruning}}) {
      sum->scored += one->scored;
      sum->correct += one->correct;
      sum->right_place_imprecise += one->right_place_imprecise;
      sum->wrong_place += one->wrong_place;
      sum->far_wrong_place += one->far_wrong_place;
      sum->false_negatives += one->false_negatives;
    }
    bounded_module_s += e.timing.candidate_selection_s + lt.time_s + e.optimisation_s;
    if (e.cost_model_s) {
      cost_model_s += *e.cost_model_s;
      has_cost_model = true;
    }
    if (e.loop_closure_cost_s && e.likelihood_posterior_cpu_s) {
      rtabmap_loop_closure_s += *e.likelihood_posterior_cpu_s + lt.time_s;
      rtabmap_loop_closure_cost_s += *e.loop_closure_cost_s;
      has_rtabmap_loop_closure = true;
    }
    ate_rmse_m.push_back(e.ate_rmse_m);
    loop_closure_s += e.loop_closure_detection_s;
    wifi_overhead_s += e.wifi_overhead_s;
    total_s += e.total_s;
    episodes += e.revisit_episodes;
    comparisons += e.candidate_comparisons;
    keyframes += e.keyframes;
  }
  double mean(double sum) const { return runs > 0 ? sum / runs : 0.0; }
  /// "mean" for one run, "mean +- sd (min-max)" over seeds.
  std::string ate_text() const {
    if (ate_rmse_m.empty()) return "-";
    double sum = 0, lo = ate_rmse_m.front(), hi = lo;
    for (double x : ate_rmse_m) {
      sum += x;
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    const double m = sum / static_cast<double>(ate_rmse_m.size());
    if (ate_rmse_m.size() == 1) return fmt::format("{:.3f}", m);
    double ss = 0;
    for (double x : ate_rmse_m) ss += (x - m) * (x - m);
    const double sd = std::sqrt(ss / static_cast<double>(ate_rmse_m.size() - 1));
    return fmt::format("{:.2f} &plusmn; {:.2f} ({:.2f}-{:.2f})", m, sd, lo, hi);
  }
};

std::string percent_of(std::int64_t part, std::int64_t whole) {
  if (whole == 0) return fmt::format("- (0/0)");
  return fmt::format("{:.1f} ({}/{})", 100.0 * static_cast<double>(part) / whole, part, whole);
}

/// cells[scene][setting][wifi]: the cases of one table cell, one per seed.
using Cells = std::map<std::string, std::map<std::string, std::map<bool, Cell>>>;

/// One table of the comparison: its title and what a cell shows.
struct Metric {
  std::string title;
  std::function<std::string(const Cell&, bool wifi)> cell;
};

/// The tables, in the order the paper's section gives them; the front-end-specific ones when a
/// case has their numbers.
std::vector<Metric> comparison_metrics(const std::vector<ComparisonCase>& cases) {
  bool any_cost_model = false, any_rtabmap_loop_closure = false;
  for (const ComparisonCase& c : cases) {
    any_cost_model |= c.evaluation.cost_model_s.has_value();
    any_rtabmap_loop_closure |= c.evaluation.loop_closure_cost_s.has_value();
  }
  std::vector<Metric> metrics = {
      {"Trajectory error: ATE RMSE (m), after the back end's pruning",
       [](const Cell& c, bool) { return c.ate_text(); }},
      {"False positive loop closures (wrong place): % of scored edges, online (false/scored)",
       [](const Cell& c, bool) { return percent_of(c.online.wrong_place, c.online.scored); }},
      {"... after pruning (edges the back end kept)",
       [](const Cell& c, bool) { return percent_of(c.pruned.wrong_place, c.pruned.scored); }},
      {"Wrong-place closures between far places (true positions > 12 m apart): online / after "
       "pruning",
       [](const Cell& c, bool) {
         return fmt::format("{} / {}", c.online.far_wrong_place, c.pruned.far_wrong_place);
       }},
      {"Right place, imprecise (within 3 m, error within 1 m / 10 deg; not false): online / after "
       "pruning",
       [](const Cell& c, bool) {
         return fmt::format("{} / {}", c.online.right_place_imprecise,
                            c.pruned.right_place_imprecise);
       }},
      {"False negatives: % of revisit episodes without a correct loop closure (missed/episodes), "
       "online",
       [](const Cell& c, bool) { return percent_of(c.online.false_negatives, c.episodes); }},
      {"... after pruning",
       [](const Cell& c, bool) { return percent_of(c.pruned.false_negatives, c.episodes); }},
      {"Loop-closure detection time (s, wall-clock)",
       [](const Cell& c, bool) { return fmt::format("{:.2f}", c.mean(c.loop_closure_s)); }},
      {"Candidate comparisons (visual transformations tried for loop closure)",
       [](const Cell& c, bool) { return fmt::format("{:.0f}", c.mean(c.comparisons)); }},
      {"Long-term comparisons (the candidates Wi-Fi bounds)",
       [](const Cell& c, bool) { return fmt::format("{:.0f}", c.mean(c.long_term_comparisons)); }},
      {"Bounded-module time: candidate selection + long-term verifications + optimisation (s)",
       [](const Cell& c, bool) { return fmt::format("{:.2f}", c.mean(c.bounded_module_s)); }},
      {"Wi-Fi overhead: clustering + cluster management (ms, % of pipeline time)",
       [](const Cell& c, bool wifi) {
         if (!wifi) return std::string("-");
         return fmt::format("{:.1f} ({:.3f} %)", 1e3 * c.mean(c.wifi_overhead_s),
                            c.total_s > 0 ? 100.0 * c.wifi_overhead_s / c.total_s : 0.0);
       }},
  };
  if (any_cost_model) {
    metrics.push_back(
        {"Front-end time, deterministic cost model (s; what rtabmap's Rtabmap/TimeThr compares)",
         [](const Cell& c, bool) {
           return c.has_cost_model ? fmt::format("{:.2f}", c.mean(c.cost_model_s))
                                   : std::string("-");
         }});
  }

  if (any_rtabmap_loop_closure) {
    // The paper's RTAB-Map time table: loop-closure detection as Rtabmap::process times it, not
    // the pipeline's module (which also holds quantisation, proximity and predecessor links).
    const auto rtabmap_cell = [](double Cell::*seconds) {
      return [seconds](const Cell& c, bool) {
        return c.has_rtabmap_loop_closure ? fmt::format("{:.3f}", c.mean(c.*seconds))
                                          : std::string("-");
      };
    };
    metrics.push_back(
        {"RTAB-Map loop-closure time: likelihood + posterior + loop hypothesis "
         "verification (s; thread CPU + verification wall-clock)",
         rtabmap_cell(&Cell::rtabmap_loop_closure_s)});
    metrics.push_back({"... the same, deterministic cost model (s)",
                       rtabmap_cell(&Cell::rtabmap_loop_closure_cost_s)});
  }

  return metrics;
}

/// A cell with no run (an external system's Wi-Fi variant when it reads no Wi-Fi, or runs that
/// all failed) shows "-".
void metric_table(std::string& out, const Metric& metric, const std::vector<std::string>& scenes,
                  const std::vector<std::string>& settings, Cells& cells) {
  out += "### " + metric.title + "\n\n| scene |";
  std::string rule = "| --- |";
  for (const std::string& setting : settings) {
    out += fmt::format(" {} Vanilla | {} WiFi |", setting, setting);
    rule += " ---: | ---: |";
  }
  out += "\n" + rule + "\n";
  for (const std::string& scene : scenes) {
    out += "| " + scene + " |";
    for (const std::string& setting : settings) {
      for (bool wifi : {false, true}) {
        const Cell& cell = cells[scene][setting][wifi];
        out += " " + (cell.runs > 0 ? metric.cell(cell, wifi) : std::string("-")) + " |";
      }
    }
    out += "\n";
  }
  out += "\n";
}

/// Time, Wi-Fi relative to vanilla, per scene and setting.
void ratio_table(std::string& out, const std::string& title, double Cell::*seconds,
                 const std::vector<std::string>& scenes, const std::vector<std::string>& settings,
                 Cells& cells) {
  out += "### " + title + ", WiFi / Vanilla (ratio, same run)\n\n| scene |";
  std::string rule = "| --- |";
  for (const std::string& setting : settings) {
    out += " " + setting + " |";
    rule += " ---: |";
  }
  out += "\n" + rule + "\n";
  for (const std::string& scene : scenes) {
    out += "| " + scene + " |";
    for (const std::string& setting : settings) {
      const Cell& v = cells[scene][setting][false];
      const Cell& w = cells[scene][setting][true];
      out += v.*seconds > 0 && w.runs > 0 ? fmt::format(" {:.2f} |", w.*seconds / v.*seconds)
                                          : std::string(" - |");
    }
    out += "\n";
  }
}

/// The runs that gave no evaluation (external systems that failed, timed out or wrote nothing
/// usable), with why: they count in no table.
void failed_runs_table(std::string& out, const std::vector<ComparisonCase>& cases) {
  std::string rows;
  for (const ComparisonCase& c : cases) {
    if (c.status == "ok") continue;
    rows += fmt::format("| {} | {} | {} | {} | {} | {} |\n", c.scene, c.seed, c.setting,
                        c.wifi ? "wifi" : "vanilla", c.status, c.run_dir.string());
  }
  if (rows.empty()) return;
  out +=
      "\n### Runs that failed (in no table above; each run folder holds run.json, stdout.log and "
      "stderr.log)\n\n| scene | seed | setting | variant | status | run folder |\n| --- | ---: "
      "| --- | --- | --- | --- |\n" +
      rows;
}

void divergence_table(std::string& out, const std::vector<PairDivergence>& divergences) {
  out +=
      "\n### First keyframe where the WiFi run differs from vanilla (same dataset and "
      "random draws)\n\n| scene | seed | setting | keyframe | time since first keyframe (s) |\n| "
      "--- | ---: | --- | "
      "---: | ---: |\n";
  for (const PairDivergence& d : divergences) {
    out += d.keyframe < 0 ? fmt::format("| {} | {} | {} | none | - |\n", d.scene, d.seed, d.setting)
                          : fmt::format("| {} | {} | {} | {} | {:.3f} |\n", d.scene, d.seed,
                                        d.setting, d.keyframe, d.time_s);
  }
}

}  // namespace

SweepAxis parse_sweep(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size()) {
    throw ParseError("--sweep", text, "expected key=value1,value2,...");
  }
  SweepAxis axis{text.substr(0, eq), {}};
  std::string rest = text.substr(eq + 1);
  std::size_t start = 0;
  while (start <= rest.size()) {
    const std::size_t comma = rest.find(',', start);
    const std::string value =
        rest.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (value.empty()) throw ParseError("--sweep", text, "empty value in the list");
    axis.values.push_back(value);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  slam::SlamOptions probe;
  for (const std::string& value : axis.values) slam::set_option(probe, axis.key, value, "--sweep");
  return axis;
}

ComparisonOptions::ComparisonOptions(const std::string& frontend,
                                     const std::vector<std::string>& assignments)
    : settings(assignments) {
  slam.frontend = frontend;
  for (const std::string& s : assignments) slam::set_option_assignment(slam, s);
  slam_seed_set = assigns_slam_seed(assignments);
}

bool assigns_slam_seed(const std::vector<std::string>& assignments) {
  return std::any_of(assignments.begin(), assignments.end(),
                     [](const std::string& s) { return s.starts_with("seed="); });
}

namespace {

/// One SLAM run of the comparison: its dataset (folder relative to the output, and the site it
/// was generated from, whose plan the plots draw) and its options.
struct RunJob {
  std::filesystem::path dataset;
  std::shared_ptr<const sim::site::Site> site;
  slam::SlamOptions slam;
  std::size_t case_index = 0;
  /// Our front ends run while the dataset is generated (study/streamed_runs.hpp): their wall
  /// time, kept for the progress line after evaluation. External systems run on the dataset.
  double slam_wall_s = 0.0;
};

/// The variants a setting runs: vanilla, and Wi-Fi unless the front end is an external system
/// that reads no Wi-Fi (its system file says so; resolving it here also refuses a missing or
/// malformed system file before any dataset is generated).
std::vector<bool> variants_of(const slam::SlamOptions& o) {
  if (interop::is_external_frontend(o.frontend) &&
      !interop::resolve_external_system(o.frontend).wifi) {
    return {false};
  }
  return {false, true};
}

void check_comparison_input(const std::vector<sim::scene::Scene>& scenes,
                            const ComparisonOptions& options) {
  if (scenes.empty()) throw InvalidInputError("compare: no scene given");
  if (options.seeds < 1) throw InvalidInputError("compare: --seeds must be >= 1");
  if (options.jobs < 1) throw InvalidInputError("compare: --jobs must be >= 1");
  sim::generate::check_max_frames(options.max_frames);
  // Every run is evaluated, and the evaluation aligns at least three poses: fewer frames failed
  // only after the datasets were rendered and every run made.
  if (options.max_frames >= 0 &&
      options.max_frames < static_cast<std::int64_t>(eval::kMinAssociatedPoses)) {
    throw InvalidInputError(
        fmt::format("compare: --max-frames {}: every run is scored against ground truth, which "
                    "aligns at least {} poses; give {} or more",
                    options.max_frames, eval::kMinAssociatedPoses, eval::kMinAssociatedPoses));
  }
  std::map<std::string, int> names;
  for (const sim::scene::Scene& scene : scenes) {
    // The scene's name names its datasets' and runs' folders and its table row.
    if (scene.name.empty()) {
      throw InvalidInputError(fmt::format(
          "compare: {}: the scene has no name; give it one (`name:`), which names its folders "
          "and its row of the tables",
          scene.source_path.empty() ? std::string("a scene") : scene.source_path));
    }
    if (++names[scene.name] > 1) {
      throw InvalidInputError("compare: scene name '" + scene.name + "' given twice");
    }
  }
}

/// Generates the dataset of jobs[first..] (one scene and seed) and runs our front ends' jobs
/// among them on its events as it is written.
void generate_and_stream(std::vector<RunJob>& jobs, std::size_t first,
                         const ComparisonOptions& options, const std::filesystem::path& out_dir,
                         const std::function<void(const std::string&)>& progress,
                         const ComparisonResult& result) {
  const RunJob& any = jobs[first];
  std::vector<StreamedRun> runs;
  std::vector<std::size_t> run_job_of;
  bool any_external = false;
  for (std::size_t j = first; j < jobs.size(); ++j) {
    if (interop::is_external_frontend(jobs[j].slam.frontend)) {
      any_external = true;
      continue;
    }
    StreamedRun run;
    run.slam = jobs[j].slam;
    run.run_dir = out_dir / result.cases[jobs[j].case_index].run_dir;
    run.run_info = {{"input", dataset_run_input(any.dataset, sim::generate::recording_of_scene(
                                                                 any.site->scene()))}};
    runs.push_back(std::move(run));
    run_job_of.push_back(j);
  }
  sim::generate::GenerateOptions generate;
  generate.max_frames = options.max_frames;
  // An external system reads the images from disk; otherwise colour only when the caller keeps
  // the dataset (the evaluation reads depth alone).
  generate.camera = options.dataset_colour || any_external
                        ? sim::generate::CameraOutput::kColourAndDepth
                        : sim::generate::CameraOutput::kDepthOnly;
  // Ctrl-C under the command's StopOnSignal guard stops the generation at its next frame (its
  // runs stop at their next event); a no-op without a guard.
  generate.on_progress = [](const sim::generate::GenerateProgress&) { throw_if_stop_requested(); };
  const sim::generate::GenerateSummary g =
      generate_with_runs(any.site, out_dir / any.dataset, generate, runs, options.jobs);
  progress(fmt::format("generated {} ({} frames, {} Wi-Fi scans, {:.0f} s){}", any.dataset.string(),
                       g.frames, g.wifi_scans, g.total_s,
                       runs.empty() ? "" : fmt::format(" with {} SLAM runs on it", runs.size())));
  for (std::size_t r = 0; r < runs.size(); ++r)
    jobs[run_job_of[r]].slam_wall_s = runs[r].summary.wall_s;
}

/// Generates each scene's dataset per seed (its site built once and kept for the plots) and lays
/// out the runs on it: every setting, vanilla and Wi-Fi. Our front ends' runs are run here, fed
/// while the dataset is generated (`options.jobs` side by side); external systems' runs are
/// left for run_job.
std::vector<RunJob> generate_datasets(const std::vector<sim::scene::Scene>& scenes,
                                      const ComparisonOptions& options,
                                      const std::vector<Setting>& settings,
                                      const std::filesystem::path& out_dir,
                                      const std::function<void(const std::string&)>& progress,
                                      ComparisonResult& result) {
  std::vector<RunJob> jobs;
  for (const sim::scene::Scene& scene : scenes) {
    result.scenes.push_back(scene.name);
    for (int k = 0; k < options.seeds; ++k) {
      const std::uint64_t seed = scene.seed + static_cast<std::uint64_t>(k);
      const std::string tag = fmt::format("{}-seed{}", scene.name, seed);
      const std::filesystem::path dataset = std::filesystem::path("datasets") / tag;
      sim::generate::GenerateOptions overrides;
      overrides.seed = seed;
      overrides.fps = options.fps;
      auto site =
          std::make_shared<const sim::site::Site>(sim::generate::resolve_scene(scene, overrides));
      result.sites.push_back(site);
      const std::size_t first_job = jobs.size();
      for (std::size_t s = 0; s < settings.size(); ++s) {
        for (bool wifi : variants_of(options_for(options, settings[s], false, seed))) {
          ComparisonCase c;
          c.scene = scene.name;
          c.seed = seed;
          c.setting = result.settings[s];
          c.wifi = wifi;
          c.run_dir = std::filesystem::path("runs") / tag / folder_of(c.setting) /
                      (wifi ? "wifi" : "vanilla");
          c.dataset_dir = dataset;
          jobs.push_back(
              {dataset, site, options_for(options, settings[s], wifi, seed), result.cases.size()});
          result.cases.push_back(std::move(c));
        }
      }
      generate_and_stream(jobs, first_job, options, out_dir, progress, result);
    }
  }
  return jobs;
}

/// Evaluates a finished run folder and writes its eval/, naming the folders where they will be
/// once the comparison's folder is in place.
void evaluate_job(const RunJob& job, const ComparisonOptions& options,
                  const std::filesystem::path& out_dir, const FinalPaths& finals,
                  ComparisonCase& c) {
  const std::filesystem::path run_dir = out_dir / c.run_dir;
  c.evaluation = eval::evaluate_run(run_dir, out_dir / job.dataset, options.eval);
  c.evaluation.run_dir = finals.of(run_dir).string();
  c.evaluation.dataset_dir = finals.of(out_dir / job.dataset).string();
  eval::write_evaluation(run_dir / "eval", c.evaluation, options.plots,
                         {&job.site->world().plan, ""});
}

/// An external system's run: its failures (exit status, timeout, outputs eval cannot score)
/// become the case's status, never an exception that would end the comparison.
void run_external_job(const RunJob& job, const ComparisonOptions& options,
                      const std::filesystem::path& out_dir, const FinalPaths& finals,
                      ComparisonCase& c, const std::function<void(const std::string&)>& progress) {
  interop::ExternalRunRequest request = interop::external_run_request(
      job.slam.frontend, c.wifi, out_dir / job.dataset, out_dir / c.run_dir);
  request.seed = job.slam.seed;
  request.extra_run_info = {
      {"input", dataset_run_input(job.dataset, recording_of_dataset(out_dir / job.dataset))}};
  request.within = finals;
  const interop::ExternalRunResult result = interop::run_external_system(request);
  c.status = result.status;
  if (result.ok) {
    try {
      evaluate_job(job, options, out_dir, finals, c);
    } catch (const StoppedBySignal&) {
      throw;  // Ctrl-C while scoring: not the run's status (a study would store it as finished)
    } catch (const Error& e) {  // what the system wrote cannot be scored
      c.status = finals.in_text(std::string("not scorable: ") + e.what());
      c.evaluation = {};
    } catch (const std::filesystem::filesystem_error& e) {
      c.status = finals.in_text(std::string("not scorable: ") + e.what());
      c.evaluation = {};
    }
  }
  const std::string what = c.run_dir.parent_path().string() + (c.wifi ? " wifi" : " vanilla");
  progress(c.status == "ok"
               ? fmt::format("{}: ATE {:.3f} m, loop closures {}, {:.1f} s", what,
                             c.evaluation.ate_rmse_m, c.evaluation.loop_closures_detected,
                             result.process.wall_s)
               : fmt::format("{}: failed: {}", what, c.status));
}

/// Evaluates the job's run (ours: run while its dataset was generated; an external system's: run
/// here on the finished dataset) and writes its eval/.
void run_job(const RunJob& job, const ComparisonOptions& options,
             const std::filesystem::path& out_dir, const FinalPaths& finals, ComparisonCase& c,
             const std::function<void(const std::string&)>& progress) {
  throw_if_stop_requested();
  if (interop::is_external_frontend(job.slam.frontend)) {
    run_external_job(job, options, out_dir, finals, c, progress);
    return;
  }
  evaluate_job(job, options, out_dir, finals, c);
  progress(fmt::format("{} {}: ATE {:.3f} m, loop closures {} ({} false), {:.1f} s",
                       c.run_dir.parent_path().string(), c.wifi ? "wifi" : "vanilla",
                       c.evaluation.ate_rmse_m, c.evaluation.loop_closures_detected,
                       c.evaluation.false_positives, job.slam_wall_s));
}

/// Where each Wi-Fi run first departs from its vanilla twin (our front ends: an external run has
/// no keyframe graph to compare).
std::vector<PairDivergence> pair_divergences(const std::vector<ComparisonCase>& cases,
                                             const std::filesystem::path& out_dir) {
  std::vector<PairDivergence> out;
  for (const ComparisonCase& w : cases) {
    if (!w.wifi || interop::is_external_frontend(w.evaluation.frontend) || w.status != "ok")
      continue;
    for (const ComparisonCase& v : cases) {
      if (v.wifi || v.scene != w.scene || v.seed != w.seed || v.setting != w.setting) continue;
      const std::optional<eval::RunDivergence> d =
          eval::first_divergence(out_dir / v.run_dir, out_dir / w.run_dir);
      out.push_back({w.scene, w.seed, w.setting, d ? d->keyframe : -1, d ? d->time_s : 0.0});
    }
  }
  return out;
}

}  // namespace

std::vector<std::filesystem::path> comparison_input_files(const ComparisonOptions& options) {
  std::vector<std::filesystem::path> out;
  for (const Setting& s : expand(options.sweeps)) {
    for (std::filesystem::path& file : files_read_by(options_for(options, s, true, 1)))
      out.push_back(std::move(file));
  }
  return out;
}

ComparisonResult run_comparison(const std::vector<sim::scene::Scene>& scenes,
                                const ComparisonOptions& options,
                                const std::filesystem::path& out_dir, const FinalPaths& finals) {
  check_comparison_input(scenes, options);
  // One place per option: a key swept twice, or set and swept, would leave one of its values
  // silently unused.
  std::set<std::string> swept;
  for (const SweepAxis& axis : options.sweeps) {
    if (!swept.insert(axis.key).second) {
      throw InvalidInputError(fmt::format(
          "compare: --sweep {0} given twice; give its values once (--sweep {0}=a,b,c)", axis.key));
    }
  }
  // Every setting runs vanilla and with Wi-Fi: a `wifi` option would be overridden by each run.
  const auto refuse_wifi = [](const std::string& given) {
    throw InvalidInputError(fmt::format(
        "compare: {}: compare runs every setting both vanilla and with Wi-Fi, so the 'wifi' "
        "option would change nothing (tune the Wi-Fi module by wifi_similarity and the other "
        "wifi_* options)",
        given));
  };
  if (swept.count("wifi")) refuse_wifi("--sweep wifi=...");
  for (const std::string& assignment : options.settings) {
    const std::string key = assignment.substr(0, assignment.find('='));
    if (key == "wifi") refuse_wifi("--set " + assignment);
    if (swept.count(key)) {
      throw InvalidInputError(
          fmt::format("compare: {0} is both set (--set {1}) and swept (--sweep {0}=...); keep one",
                      key, assignment));
    }
  }
  ComparisonResult result;
  result.seeds = options.seeds;
  const std::vector<Setting> settings = expand(options.sweeps);
  for (const Setting& s : settings) result.settings.push_back(label_of(options.settings, s));
  // Every option combination, front end included, is checked before any dataset is generated;
  // two settings must not share a run folder.
  std::map<std::string, std::string> label_of_folder;
  for (const std::string& label : result.settings) {
    const auto [at, added] = label_of_folder.emplace(folder_of(label), label);
    if (!added) {
      throw InvalidInputError(
          fmt::format("compare: settings '{}' and '{}' would share the run "
                      "folder '{}'; name one differently",
                      at->second, label, at->first));
    }
  }
  for (const Setting& s : settings) {
    const slam::SlamOptions o = options_for(options, s, true, 1);
    if (const std::optional<std::string> problem = front_end_problem(o.frontend)) {
      throw InvalidInputError("compare: " + *problem);
    }
  }

  std::mutex progress_mutex;
  const std::function<void(const std::string&)> progress = [&](const std::string& line) {
    if (!options.on_progress) return;
    std::lock_guard lock(progress_mutex);
    options.on_progress(line);
  };
  const std::vector<RunJob> jobs =
      generate_datasets(scenes, options, settings, out_dir, progress, result);
  // Evaluations (and external systems' runs), `jobs` at a time; each writes only its own folder
  // and case.
  parallel_for(clamp_thread_count(options.jobs), jobs.size(), [&](std::size_t i) {
    run_job(jobs[i], options, out_dir, finals, result.cases[jobs[i].case_index], progress);
  });
  result.divergences = pair_divergences(result.cases, out_dir);

  write_file_atomic(out_dir / "comparison.md", result.markdown());
  write_file_atomic(out_dir / "comparison.csv", result.csv());
  write_file_atomic(out_dir / "comparison.json", result.to_json().dump(1) + "\n");
  return result;
}

std::string ComparisonResult::markdown() const {
  Cells cells;
  for (const ComparisonCase& c : cases) {
    if (c.status == "ok") cells[c.scene][c.setting][c.wifi].add(c.evaluation);
  }
  bool any_cost_model = false, any_rtabmap_loop_closure = false;
  for (const ComparisonCase& c : cases) {
    any_cost_model |= c.evaluation.cost_model_s.has_value();
    any_rtabmap_loop_closure |= c.evaluation.loop_closure_cost_s.has_value();
  }
  std::string out;
  if (seeds > 1) {
    out += fmt::format(
        "Each cell: {} seeds; ATE as mean &plusmn; standard deviation (min-max), times and "
        "comparisons averaged, closures summed over seeds.\n\n",
        seeds);
  }
  for (const Metric& metric : comparison_metrics(cases))
    metric_table(out, metric, scenes, settings, cells);
  // Time, Wi-Fi relative to vanilla: the paper's headline (loop-closure detection) and its own
  // figure (the module bounding affects, plus optimisation).
  ratio_table(out, "Loop-closure detection time", &Cell::loop_closure_s, scenes, settings, cells);
  out += "\n";
  ratio_table(out, "Bounded-module time", &Cell::bounded_module_s, scenes, settings, cells);
  if (any_cost_model) {
    out += "\n";
    ratio_table(out, "Front-end time (cost model)", &Cell::cost_model_s, scenes, settings, cells);
  }
  if (any_rtabmap_loop_closure) {
    out += "\n";
    ratio_table(out, "RTAB-Map loop-closure time", &Cell::rtabmap_loop_closure_s, scenes, settings,
                cells);
    out += "\n";
    ratio_table(out, "RTAB-Map loop-closure time (cost model)", &Cell::rtabmap_loop_closure_cost_s,
                scenes, settings, cells);
  }
  failed_runs_table(out, cases);
  if (!divergences.empty()) divergence_table(out, divergences);
  return out;
}

namespace {

/// A case's metrics without the folders it names: the case's own run_dir and dataset_dir,
/// relative to the comparison's folder, say where they are.
nlohmann::ordered_json case_metrics(const ComparisonCase& c) {
  nlohmann::ordered_json flat = c.evaluation.flat_metrics();
  flat.erase("run_dir");
  flat.erase("dataset_dir");
  return flat;
}

}  // namespace

std::string ComparisonResult::csv() const {
  // Every metric any case has, in the order they first appear: cases differ (a front end's own
  // counters, a failed run's missing ones), and the first case's set alone would drop the
  // others'.
  std::vector<std::string> keys;
  std::set<std::string> known;
  std::vector<nlohmann::ordered_json> metrics;
  for (const ComparisonCase& c : cases) {
    metrics.push_back(case_metrics(c));
    if (c.status != "ok") continue;  // no metrics (below: empty fields)
    for (const auto& item : metrics.back().items()) {
      if (known.insert(item.key()).second) keys.push_back(item.key());
    }
  }
  std::string out = "scene,seed,setting,variant,run_dir,dataset_dir,status";
  for (const std::string& k : keys) out += "," + k;
  out += "\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const ComparisonCase& c = cases[i];
    const nlohmann::ordered_json& flat = metrics[i];
    out += fmt::format("{},{},{},{},{},{},{}", csv_field(c.scene), c.seed, csv_field(c.setting),
                       c.wifi ? "wifi" : "vanilla", csv_field(c.run_dir.string()),
                       csv_field(c.dataset_dir.string()), csv_field(c.status));
    // A failed run's metrics are empty fields, not zeros that would read as a perfect score.
    for (const std::string& k : keys) {
      out += "," + (c.status == "ok" && flat.contains(k) ? csv_field(flat[k]) : "");
    }
    out += "\n";
  }
  return out;
}

nlohmann::json ComparisonResult::to_json() const {
  nlohmann::json runs = nlohmann::json::array();
  for (const ComparisonCase& c : cases) {
    runs.push_back({{"scene", c.scene},
                    {"seed", c.seed},
                    {"setting", c.setting},
                    {"variant", c.wifi ? "wifi" : "vanilla"},
                    {"run_dir", c.run_dir.string()},
                    {"dataset_dir", c.dataset_dir.string()},
                    {"status", c.status},
                    {"metrics", c.status == "ok" ? nlohmann::json(case_metrics(c))
                                                 : nlohmann::json(nullptr)}});
  }
  nlohmann::json divergence = nlohmann::json::array();
  for (const PairDivergence& d : divergences) {
    divergence.push_back({{"scene", d.scene},
                          {"seed", d.seed},
                          {"setting", d.setting},
                          {"first_divergent_keyframe", d.keyframe},
                          {"time_s", d.time_s}});
  }
  return {{"scenes", scenes},
          {"settings", settings},
          {"seeds", seeds},
          {"runs", runs},
          {"divergence", divergence}};
}

}  // namespace wifislam::study
