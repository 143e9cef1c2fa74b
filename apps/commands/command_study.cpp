// `wifislam study ...`: studies over scene keys and SLAM options (study/study_file.hpp),
// results in SQLite, resumable, sharded, and spread over a Slurm cluster.
//
//   study cases FILE                      list the cases (id and axis values)
//   study run FILE -o DB [--shard i/N]    run (or resume) the cases into DB
//   study merge SHARD.sqlite ... -o DB    union shard databases of one study
//   study slurm FILE --tasks N -o DIR     write (and with --submit submit) a job array + merge
//   study plot DB -o DIR                  the study's curves as PNG and SVG
//   study place SCENE --budget K -o DIR   greedy AP placement against random placement
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "apps/command_registry.hpp"
#include "apps/option_validators.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "sim/scene/scene_loader.hpp"
#include "slam/slam_options.hpp"
#include "study/greedy_placement.hpp"
#include "study/output_database.hpp"
#include "study/placement_files.hpp"
#include "study/result_store.hpp"
#include "study/slurm_job.hpp"
#include "study/study_file.hpp"
#include "study/study_plot.hpp"
#include "study/study_runner.hpp"

namespace {

namespace fs = std::filesystem;
using namespace wifislam;

struct RunArgs {
  std::string file, output, shard = "0/1";
  int jobs = 1;
  bool force = false, quiet = false;
};

void run_study_command(const RunArgs& args) {
  const study::StudyFile file = study::load_study_file(args.file);
  const auto [index, count] = study::parse_shard(args.shard);
  study::prepare_run_database(args.output, file, args.force, {args.file, file.scene_path});
  study::StudyRunOptions options;
  options.database = args.output;
  options.shard_index = index;
  options.shard_count = count;
  options.jobs = args.jobs;
  if (!args.quiet) {
    options.on_progress = [](const std::string& line) { fmt::print(stderr, "study: {}\n", line); };
  }
  const study::StudyRunSummary s = study::run_study(file, options);
  fmt::print("study {}: shard {}/{}: {} cases, {} already done, {} run in {:.1f} s -> {}\n",
             file.name, index, count, s.cases, s.skipped, s.ran, s.wall_s, args.output);
}

struct SlurmArgs {
  std::string file, output, partition, time_limit;
  int tasks = 1, cpus = 1;
  bool submit = false, force = false;
};

void slurm_command(const SlurmArgs& args) {
  const study::StudyFile file = study::load_study_file(args.file);
  study::check_cases(file);
  const bool replace = check_output_folder({args.output, args.force, {}, {args.file}});
  study::SlurmJobRequest request;
  request.wifislam_binary = study::own_binary();
  request.study_file = fs::absolute(args.file).lexically_normal();
  request.tasks = args.tasks;
  request.cpus_per_task = args.cpus;
  request.partition = args.partition;
  request.time_limit = args.time_limit;
  const fs::path folder = fs::absolute(args.output).lexically_normal();
  const study::SlurmJobFiles files = study::slurm_job_files(file, request, folder);
  study::write_slurm_job(folder, replace, files);
  fmt::print("wrote {0}/study.sbatch ({1} tasks) and {0}/merge.sbatch\n", folder.string(),
             args.tasks);
  if (!args.submit) {
    fmt::print(
        "submit: cd {} && J=$(sbatch --parsable study.sbatch) && sbatch "
        "--dependency=afterok:$J merge.sbatch\n",
        folder.string());
    return;
  }
  const study::SubmittedSlurmJob job = study::submit_slurm_job(folder);
  fmt::print("submitted array job {} and merge job {}; merged database: {}/{}\n", job.array_id,
             job.merge_id, folder.string(), files.merged_database.string());
}

struct PlotArgs {
  std::string database, output;
  bool force = false;
};

void plot_command(const PlotArgs& args) {
  const study::ResultTable table = study::read_results(args.database);
  if (table.rows.empty()) {
    throw InvalidInputError(args.database + ": the study database has no results yet");
  }
  const bool replace = check_output_folder({args.output, args.force, {}, {args.database}});
  AtomicDirectory out(args.output, replace);
  const study::StudyPlotSummary summary = study::plot_study(table, out.staging_path());
  out.commit();
  fmt::print("study {}: {} rows, x = {}{}{} -> {}/ ({} figures, curves.csv)\n", table.identity.name,
             table.rows.size(), summary.x_axis.empty() ? "(none)" : summary.x_axis,
             summary.line_axes.empty()
                 ? ""
                 : ", lines by " + fmt::format("{}", fmt::join(summary.line_axes, ", ")),
             summary.pooled_axes.empty()
                 ? ""
                 : ", pooled over " + fmt::format("{}", fmt::join(summary.pooled_axes, ", ")),
             args.output, summary.figures.size());
}

struct PlaceArgs {
  std::string scene, output, seed;
  int budget = 0, random_draws = 5;
  double spacing_m = 3.0;
  std::vector<std::string> settings;
  bool force = false, quiet = false;
};

void place_command(const PlaceArgs& args) {
  const sim::Scene scene = sim::load_scene_file(args.scene);
  slam::SlamOptions slam_options;
  for (const std::string& s : args.settings) slam::set_option_assignment(slam_options, s);
  slam::validate(slam_options);
  const bool replace = check_output_folder({args.output, args.force, {}, {args.scene}});
  study::PlacementOptions options;
  options.budget = args.budget;
  options.candidate_spacing_m = args.spacing_m;
  options.random_draws = args.random_draws;
  options.seed = args.seed.empty() ? scene.seed : std::stoull(args.seed);
  options.wifi = slam_options.wifi;
  if (!args.quiet) {
    options.on_progress = [](const std::string& line) { fmt::print(stderr, "place: {}\n", line); };
  }
  const study::PlacementResult result = study::greedy_placement(scene, options);

  fmt::print("{}", study::placement_table(result));
  AtomicDirectory out(args.output, replace);
  study::write_placement_files(result, options, args.scene, scene.name, out.staging_path());
  out.commit();
  fmt::print(
      "{} candidates, {} pauses -> {}/ (placement.csv, access_points.yaml, placement and "
      "resolution figures)\n",
      result.candidates.size(), result.pause_positions_m.size(), args.output);
}

void add_cases_command(CLI::App* app) {
  auto file = std::make_shared<std::string>();
  CLI::App* cases = app->add_subcommand("cases", "List a study file's cases: id and axis values");
  cases->add_option("file", *file, "Study file (YAML)")->required();
  cases->callback([file] {
    const study::StudyFile s = study::load_study_file(*file);
    std::string header = "case_id";
    for (const study::StudyAxis& a : s.axes) header += "\t" + a.key;
    fmt::print("{}\n", header);
    for (const study::StudyCase& c : s.cases) {
      std::string line = c.id;
      for (const std::string& v : c.values) line += "\t" + v;
      fmt::print("{}\n", line);
    }
    study::check_cases(s);
    fmt::print(stderr, "study {}: {} cases, level {}, every case's scene and options check\n",
               s.name, s.cases.size(), study::to_string(s.level));
  });
}

void add_run_command(CLI::App* app) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* run = app->add_subcommand(
      "run", "Run a study's cases (or one shard's) into an SQLite database; a rerun resumes");
  run->add_option("file", args->file, "Study file (YAML)")->required();
  run->add_option("-o,--output", args->output,
                  "Database file. An existing database of the same study is resumed (its\n"
                  "finished cases are skipped): the one exception to replacing only with --force")
      ->required();
  run->add_option("--shard", args->shard,
                  "i/N: run the cases whose index is i modulo N (0 <= i < N)")
      ->capture_default_str();
  run->add_option(
         "--jobs", args->jobs,
         "Radio cases (or a SLAM case's two runs) in parallel; results do not depend on it")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  run->add_flag("--force", args->force, "Replace a database of another study");
  run->add_flag("-q,--quiet", args->quiet, "No progress lines on stderr");
  run->footer(
      "Tables: study (name, study file hash, version, level, axes), results (one row per case\n"
      "x variant: case_id, case_index, variant, one column per axis, every metric,\n"
      "software_version, scene_hash; deterministic), timing (wall-clock seconds). A killed run\n"
      "loses at most the case in flight; run it again to finish.");
  run->callback([args] { run_study_command(*args); });
}

void add_merge_command(CLI::App* app) {
  auto inputs = std::make_shared<std::vector<std::string>>();
  auto output = std::make_shared<std::string>();
  auto force = std::make_shared<bool>(false);
  CLI::App* merge =
      app->add_subcommand("merge", "Union shard databases of one study into one database");
  merge->add_option("shards", *inputs, "Shard databases")->required();
  merge->add_option("-o,--output", *output, "Merged database (a new file)")->required();
  merge->add_flag("--force", *force, "Replace an existing study database");
  merge->callback([inputs, output, force] {
    std::vector<fs::path> paths(inputs->begin(), inputs->end());
    study::prepare_merged_database(*output, *force, paths);
    const std::int64_t rows = study::merge_study_databases(paths, *output);
    fmt::print("merged {} shard databases: {} rows -> {}\n", paths.size(), rows, *output);
  });
}

void add_slurm_command(CLI::App* app) {
  auto args = std::make_shared<SlurmArgs>();
  CLI::App* slurm = app->add_subcommand(
      "slurm",
      "Write a Slurm job array (one shard per task) and a dependent merge job for a study;\n"
      "--submit also submits both with sbatch");
  slurm->add_option("file", args->file, "Study file (YAML)")->required();
  slurm->add_option("--tasks", args->tasks, "Array tasks = shards")
      ->required()
      ->check(CLI::Range(1, 100000));
  slurm->add_option("--cpus-per-task", args->cpus, "CPUs per task (the shard's --jobs)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1024));
  slurm->add_option("--partition", args->partition, "Slurm partition (default: the cluster's)");
  slurm->add_option("--time", args->time_limit, "Time limit per task, e.g. 02:00:00");
  slurm
      ->add_option("-o,--output", args->output,
                   "Job folder: study.sbatch, merge.sbatch, shards/, logs/, and the merged\n"
                   "database once the merge job ran. On a cluster, a path every node sees")
      ->required();
  slurm->add_flag("--submit", args->submit, "Submit the array, then the merge (afterok)");
  slurm->add_flag("--force", args->force, "Replace an existing job folder of this tool");
  slurm->callback([args] { slurm_command(*args); });
}

void add_plot_command(CLI::App* app) {
  auto args = std::make_shared<PlotArgs>();
  CLI::App* plot = app->add_subcommand(
      "plot", "Draw a study database's curves (PNG and SVG, one figure per metric)");
  plot->add_option("database", args->database, "Study database (study run or merge)")
      ->required()
      ->check(CLI::ExistingFile);
  plot->add_option("-o,--output", args->output, "Folder for the figures and curves.csv")
      ->required();
  plot->add_flag("--force", args->force, "Replace an existing output folder of this tool");
  plot->footer(
      "x is access_points.count or appearance.aliasing when the study sweeps one, else its "
      "first\n"
      "numeric axis; seeds are pooled (median, band min-max); every other swept axis and the\n"
      "variant (vanilla dashed, Wi-Fi solid) split the lines, so placements or wall materials\n"
      "stand side by side. curves.csv holds every point: metric, line, x, cases, median, min, "
      "max.");
  plot->callback([args] { plot_command(*args); });
}

void add_place_command(CLI::App* app) {
  auto args = std::make_shared<PlaceArgs>();
  CLI::App* place = app->add_subcommand(
      "place",
      "Greedy access-point placement: add APs one at a time, each at the candidate position\n"
      "(rooms, corridors, halls) that best tells places along the route apart, next to the same\n"
      "numbers of APs placed at random among the same candidates (radio level, no rendering)");
  place->add_option("scene", args->scene, "Scene file (YAML): the plan, route and radio")
      ->required();
  place->add_option("--budget", args->budget, "Access points to place")
      ->required()
      ->check(CLI::Range(1, study::kMaxPlacementCandidates));
  place
      ->add_option("-o,--output", args->output,
                   "Folder: placement.csv, access_points.yaml (a scene block),\n"
                   "placement.png/.svg (positions), error.png/.svg and resolution.png/.svg\n"
                   "(greedy vs random)")
      ->required();
  place->add_option("--spacing", args->spacing_m, "Candidate positions no closer than this [m]")
      ->capture_default_str()
      ->check(CLI::Range(0.5, 1000.0));
  place
      ->add_option("--random-draws", args->random_draws,
                   "Random placements per count (their median is reported)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  place->add_option("--seed", args->seed, "Seed of the random placements (default: the scene's)")
      ->check(cli::kSeedValidator);
  place->add_option("--set", args->settings,
                    "SLAM option key=value for the Wi-Fi module, e.g. --set wifi_similarity=0.85");
  place->add_flag("--force", args->force, "Replace an existing output folder of this tool");
  place->add_flag("-q,--quiet", args->quiet, "No progress lines on stderr");
  place->footer(
      "Resolution: the distance beyond which the median similarity of the route's pause pairs\n"
      "stays below wifi_similarity (smaller tells closer places apart; 'none': places never "
      "look\n"
      "different, or not even the nearest are recognised, as with one AP). Each step minimises\n"
      "it, then the share of pairs over\n"
      "12 m counted similar, then maximises the share under 4 m. Every candidate's scans are\n"
      "simulated once and each placement keeps its APs' readings, so greedy and random see the\n"
      "same draws.");
  place->callback([args] { place_command(*args); });
}

}  // namespace

WIFISLAM_COMMAND(study, 70) {
  CLI::App* app = parent.add_subcommand(
      "study",
      "Studies: sweep scene keys (access-point count, placement, power, walls, shadowing, pause\n"
      "spacing, aliasing) and SLAM options over the product of their values, at radio level (no\n"
      "rendering) or SLAM level (vanilla and Wi-Fi), into one SQLite database; resumable,\n"
      "sharded, and spread over a Slurm cluster. Study files: studies/*.yaml.");
  app->require_subcommand(1);
  add_cases_command(app);
  add_run_command(app);
  add_merge_command(app);
  add_slurm_command(app);
  add_plot_command(app);
  add_place_command(app);
}
