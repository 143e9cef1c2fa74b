// `wifislam paper -o DIR [--seeds N] [--fps F] [--parts ...] [--twins ...] [--jobs J]`: every
// table and figure of the paper's evaluation on the four twins, the paper's numbers beside ours
// with a verdict (study/paper/).
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "apps/command_registry.hpp"
#include "apps/option_validators.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "core/shell_quoted.hpp"
#include "core/stop_signal.hpp"
#include "core/thread_start.hpp"
#include "study/paper/paper_folder.hpp"
#include "study/paper/paper_report.hpp"
#include "study/paper/paper_runner.hpp"
#include "study/slurm_job.hpp"
#include "study/study_runner.hpp"

namespace wifislam::cli {

namespace {

namespace fs = std::filesystem;

struct PaperArgs {
  std::string output, parts = "rgbdslam,rtabmap,orbslam,fabmap",
                      twins = "c_hall,b_hall,j_hall,a_hall", shard, partition, time_limit;
  int seeds = 1, jobs = 0, slurm_tasks = 0, cpus = 2;
  std::string slurm_options_given;  // a --slurm-only option given, for the refusal without it
  double fps = 3.0;
  bool force = false, report_only = false, no_report = false, quiet = false, submit = false;
};

/// `--slurm N`: the folder prepared here, then a job array of N tasks, each `paper --shard i/N
/// --no-report` with these options, and a final job writing the report once all succeeded.
void write_slurm_jobs(const PaperArgs& args, const study::paper::PaperRunOptions& options) {
  study::paper::prepare_paper_folder(options);
  const fs::path dir = absolute_folder(options.folder);
  const std::string common =
      fmt::format("{} paper -o {} --seeds {} --fps {} --parts {} --twins {}",
                  shell_quoted(study::own_binary().string()), shell_quoted(dir.string()),
                  args.seeds, args.fps, shell_quoted(args.parts), shell_quoted(args.twins));
  study::SlurmArrayJob job;
  job.name = "paper";
  job.what = fmt::format("wifislam paper: {} seed(s) of {} on {}, in {} tasks (--shard i/N).",
                         args.seeds, args.parts, args.twins, args.slurm_tasks);
  job.final_what = "wifislam paper: the report, once every task has succeeded.";
  job.tasks = args.slurm_tasks;
  job.cpus_per_task = args.cpus;
  job.partition = args.partition;
  job.time_limit = args.time_limit;
  job.task_command = fmt::format(
      "{} --jobs {} --shard \"${{SLURM_ARRAY_TASK_ID}}/{}\" "
      "--no-report -q",
      common, args.cpus, args.slurm_tasks);
  job.final_command = common + " --report-only";
  job.array_file = "paper.sbatch";
  job.final_file = "report.sbatch";
  const fs::path folder = dir / "slurm";
  const study::SlurmJobFiles files = study::slurm_array_files(job, folder);
  study::write_slurm_job(folder, fs::exists(folder), files);
  fmt::print("wrote {0}/paper.sbatch ({1} tasks) and {0}/report.sbatch\n", folder.string(),
             args.slurm_tasks);
  if (!args.submit) {
    fmt::print(
        "submit: cd {} && J=$(sbatch --parsable paper.sbatch) && sbatch "
        "--dependency=afterok:$J report.sbatch\n",
        shell_quoted(folder.string()));
    return;
  }
  const study::SubmittedSlurmJob submitted = study::submit_slurm_job(folder, files);
  fmt::print("submitted array job {} and report job {}; the report: {}/report.md\n",
             submitted.array_id, submitted.merge_id, dir.string());
}

std::vector<std::string> split(const std::string& text, const std::string& option) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (item.empty()) throw ParseError(option, text, "empty name in the list");
    if (std::find(out.begin(), out.end(), item) != out.end()) {
      throw ParseError(option, text, "'" + item + "' is listed twice");
    }
    out.push_back(item);
  }
  if (out.empty() || text.back() == ',') throw ParseError(option, text, "empty name in the list");
  return out;
}

void run(const PaperArgs& args) {
  study::paper::PaperRunOptions options;
  options.folder = args.output;
  options.parts.clear();
  for (const std::string& name : split(args.parts, "--parts")) {
    const auto part = study::paper::parse_part(name);
    const auto& runnable = study::paper::runnable_parts();
    if (!part || std::find(runnable.begin(), runnable.end(), *part) == runnable.end()) {
      throw ParseError("--parts", name, "unknown part; known: rgbdslam, rtabmap, orbslam, fabmap");
    }
    options.parts.push_back(*part);
  }
  options.twins.clear();
  for (const std::string& twin : split(args.twins, "--twins")) {
    try {
      (void)study::paper::twin_scene_yaml(twin);
    } catch (const Error& e) {
      throw ParseError("--twins", twin, e.what());
    }
    options.twins.push_back(twin);
  }
  options.seeds = args.seeds;
  options.settings.fps = args.fps;
  options.jobs = clamp_thread_count(args.jobs);
  options.force = args.force;
  if (!args.shard.empty()) {
    std::tie(options.shard_index, options.shard_count) = study::parse_shard(args.shard);
  }
  if (!args.quiet) {
    options.on_progress = [](const std::string& line) { fmt::print(stderr, "paper: {}\n", line); };
  }
  if (args.submit && args.slurm_tasks == 0) {
    throw ParseError("--submit", "", "submits the jobs --slurm N writes: give --slurm too");
  }
  if (!args.slurm_options_given.empty() && args.slurm_tasks == 0) {
    // Ignored, the whole reproduction would start here instead of on the cluster.
    throw ParseError(args.slurm_options_given, "",
                     "applies to the jobs --slurm N writes: give --slurm too");
  }
  if (args.slurm_tasks > 0) {
    if (args.report_only || !args.shard.empty()) {
      throw ParseError("--slurm", std::to_string(args.slurm_tasks),
                       "writes the tasks' jobs: not with --report-only or --shard");
    }
    write_slurm_jobs(args, options);
    return;
  }
  // Ctrl-C (or scancel's SIGTERM) stops the runs at the next frame and removes the twin's
  // scratch folder; the cases stored so far stay, and a rerun continues from them. One during the
  // report lets it finish (its files are written whole) and then ends the process.
  const StopOnSignal stop_on_signal;
  if (args.report_only) {
    if (!fs::exists(options.folder / study::paper::folder::kIdentity)) {
      throw InvalidInputError(
          fmt::format("{}: not a paper folder (no {}); run `wifislam paper "
                      "-o {}` first",
                      args.output, study::paper::folder::kIdentity, args.output));
    }
  } else {
    const study::paper::PaperRunSummary s = study::paper::run_paper(options);
    if (!args.quiet) {
      fmt::print(stderr,
                 "paper: {} runs and {} localisations made, {} cases already done ({:.0f} s)\n",
                 s.runs, s.localisations, s.cases_skipped, s.wall_s);
    }
  }
  if (args.no_report) return;
  const std::string verdicts = study::paper::write_paper_report(options.folder);
  fmt::print("{}\nwrote {}/report.md (and a page per part, paper_vs_ours.csv/.json, figures/)\n",
             verdicts, absolute_folder(options.folder).string());
}

}  // namespace

WIFISLAM_COMMAND(paper, 66) {
  auto args = std::make_shared<PaperArgs>();
  CLI::App* app = parent.add_subcommand(
      "paper",
      "Reproduce the paper's evaluation on the twins of its four buildings: RGBD-SLAM on C Hall\n"
      "(min-matches x inlier distance), RTAB-Map on all four (real-time thresholds), ORB-SLAM on\n"
      "B, C and J Hall (min-matches) and A Hall, and the FAB-MAP comparison; then write the\n"
      "report: every number of the paper beside ours (mean, sd and min-max over seeds) with a\n"
      "verdict (reproduced, direction only, departs, not applicable), one page per part, the\n"
      "figures redrawn. Resumable: run it again on the same folder to continue; nothing done is\n"
      "redone. Each twin's rendering is shared by all its runs.");
  app->add_option("-o,--output", args->output,
                  "Paper folder: made if new, continued if `paper` made it")
      ->required()
      ->check(kNonEmptyPath);
  app->add_option("--seeds", args->seeds, "Seeds per twin (its own seed, +1, ...)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  app->add_option("--fps", args->fps, "Frame rate of every twin's dataset")
      ->capture_default_str()
      ->check(cli::finite_range(0.1, 30.0));
  app->add_option("--parts", args->parts, "Parts to run, comma-separated")->capture_default_str();
  app->add_option("--twins", args->twins, "Twins to run, comma-separated")->capture_default_str();
  app->add_option("--jobs", args->jobs,
                  "SLAM runs at a time (default: one per core; 1 keeps times free of\n"
                  "interference; results are the same)")
      ->check(at_least(0));
  app->add_option("--shard", args->shard,
                  "i/N: run only every N-th twin-and-seed group from the i-th (a cluster's task)");
  app->add_flag("--report-only", args->report_only, "Write the report from what DIR holds");
  app->add_option("--slurm", args->slurm_tasks,
                  "N: write DIR/slurm/paper.sbatch (an N-task job array, task i running\n"
                  "--shard i/N) and report.sbatch (the report, once every task succeeded)")
      ->check(CLI::Range(1, 100000));
  app->add_option("--cpus-per-task", args->cpus, "With --slurm: CPUs per task (its --jobs)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1024));
  app->add_option("--partition", args->partition, "With --slurm: the Slurm partition")
      ->check(cli::kSlurmPartition);
  app->add_option("--time", args->time_limit, "With --slurm: time limit per task, e.g. 02:00:00")
      ->check(cli::kSlurmTime);
  app->add_flag("--submit", args->submit, "With --slurm: submit both jobs with sbatch");
  app->add_flag("--no-report", args->no_report, "Run, but leave the report to a later call");
  app->add_flag("--force", args->force, "Start over: replace DIR (a folder `paper` made)");
  app->add_flag("-q,--quiet", args->quiet, "No progress lines on stderr");
  app->footer(
      "The stored five-seed report (docs/results/paper) took 280 min, about 56 min a seed,\n"
      "at the default 3 fps on 2 cores shared with other work; bench/paper/run.sh times one\n"
      "seed. DIR holds the twins' scene files, one study file and SQLite database per part,\n"
      "twin and seed (`wifislam study slurm` takes any of them), and the report. Details:\n"
      "docs/paper/README.md.");
  app->callback([args, app] {
    for (const char* option : {"--cpus-per-task", "--partition", "--time"}) {
      if (app->count(option) > 0) args->slurm_options_given = option;
    }
    run(*args);
  });
}

}  // namespace wifislam::cli
