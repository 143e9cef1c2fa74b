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
#include "apps/commands/study_subcommands.hpp"
#include "apps/option_validators.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "core/stop_signal.hpp"
#include "study/output_database.hpp"
#include "study/result_store.hpp"
#include "study/study_file.hpp"
#include "study/study_plot.hpp"
#include "study/study_runner.hpp"

namespace wifislam::cli {

namespace {

namespace fs = std::filesystem;

struct RunArgs {
  std::string file, output, shard = "0/1";
  int jobs = 1;
  bool force = false, quiet = false;
};

void print_unread_option_warnings(const study::StudyFile& file) {
  for (const std::string& w : study::unread_option_warnings(file))
    fmt::print(stderr, "study: warning: {}\n", w);
}

void run_study_command(const RunArgs& args) {
  const study::StudyFile file = study::load_study_file(args.file);
  const auto [index, count] = study::parse_shard(args.shard);
  print_unread_option_warnings(file);
  study::StudyRunOptions options;
  options.replace_database =
      study::check_run_database(args.output, file, args.force, study::input_files(file));
  options.database = args.output;
  options.shard_index = index;
  options.shard_count = count;
  options.jobs = args.jobs;
  if (!args.quiet) {
    options.on_progress = [](const std::string& line) { fmt::print(stderr, "study: {}\n", line); };
  }
  // Ctrl-C, or the SIGTERM of Slurm's scancel, stops the run between cases or at the running
  // SLAM case's next frame and removes that case's unfinished folder; the finished cases' rows
  // stay in the database, and a rerun resumes from them.
  const StopOnSignal stop_on_signal;
  const study::StudyRunSummary s = study::run_study(file, options);
  fmt::print("study {}: shard {}/{}: {} cases, {} already done, {} run in {:.1f} s -> {}\n",
             file.name, index, count, s.cases, s.skipped, s.ran, s.wall_s, args.output);
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

void add_cases_command(CLI::App* app) {
  auto file = std::make_shared<std::string>();
  CLI::App* cases = app->add_subcommand("cases", "List a study file's cases: id and axis values");
  cases->add_option("file", *file, "Study file (YAML)")->required()->check(kNonEmptyInput);
  cases->callback([file] {
    const study::StudyFile s = study::load_study_file(*file);
    // Every case checked before the table: a refused file prints no table (exit 2, stdout empty).
    study::check_cases(s);
    print_unread_option_warnings(s);
    std::string header = "case_id";
    for (const study::StudyAxis& a : s.axes) header += "\t" + a.key;
    fmt::print("{}\n", header);
    for (const study::StudyCase& c : s.cases) {
      std::string line = c.id;
      for (const std::string& v : c.values) line += "\t" + v;
      fmt::print("{}\n", line);
    }
    fmt::print(stderr, "study {}: {} cases, level {}, every case's scene and options check\n",
               s.name, s.cases.size(), study::to_string(s.level));
  });
}

void add_run_command(CLI::App* app) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* run = app->add_subcommand(
      "run", "Run a study's cases (or one shard's) into an SQLite database; a rerun resumes");
  run->add_option("file", args->file, "Study file (YAML)")->required()->check(kNonEmptyInput);
  run->add_option("-o,--output", args->output,
                  "Database file. An existing database of the same study is resumed (its\n"
                  "finished cases are skipped): the one exception to replacing only with --force")
      ->required();
  run->add_option("--shard", args->shard,
                  "i/N: run the cases whose index is i modulo N (0 <= i < N)")
      ->capture_default_str();
  run->add_option(
         "--jobs", args->jobs,
         "Radio cases (or a SLAM case's two runs, side by side on one rendering) in parallel;\n"
         "results do not depend on it")
      ->capture_default_str()
      ->check(at_least(1));
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
  merge->add_option("shards", *inputs, "Shard databases")->required()->check(kNonEmptyInput);
  merge->add_option("-o,--output", *output, "Merged database (a new file)")->required();
  merge->add_flag("--force", *force, "Replace an existing study database");
  merge->callback([inputs, output, force] {
    std::vector<fs::path> paths(inputs->begin(), inputs->end());
    study::prepare_merged_database(*output, *force, paths);
    const std::int64_t rows = study::merge_study_databases(paths, *output);
    fmt::print("merged {} shard databases: {} rows -> {}\n", paths.size(), rows, *output);
    // Merging the shards there are so far is allowed (a look at partial results), but not
    // without a word: a shard left out made a short database that read as the whole study.
    const study::CaseCount cases = study::count_cases(*output);
    if (cases.in_study && cases.with_rows < *cases.in_study) {
      fmt::print(stderr,
                 "study merge: warning: {} of the study's {} cases have rows; the rest are in "
                 "shards not given or not yet finished\n",
                 cases.with_rows, *cases.in_study);
    }
  });
}

void add_plot_command(CLI::App* app) {
  auto args = std::make_shared<PlotArgs>();
  CLI::App* plot = app->add_subcommand(
      "plot", "Draw a study database's curves (PNG and SVG, one figure per metric)");
  // No CLI::ExistingFile: a missing database is an I/O error (exit 3) named by the reader, as
  // every command's missing input is.
  plot->add_option("database", args->database, "Study database (study run or merge)")
      ->required()
      ->check(kNonEmptyInput);
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
  cli::add_study_slurm_command(app);
  add_plot_command(app);
  cli::add_study_place_command(app);
}

}  // namespace wifislam::cli
