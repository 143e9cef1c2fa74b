// `wifislam study slurm FILE --tasks N -o DIR [--submit]`: a Slurm job array (one shard per
// task) and a dependent merge job for a study (study/slurm_job.hpp does the work).
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "apps/commands/study_subcommands.hpp"
#include "apps/option_validators.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "core/shell_quoted.hpp"
#include "study/slurm_job.hpp"
#include "study/study_file.hpp"
#include "study/study_runner.hpp"

namespace wifislam::cli {

namespace {

namespace fs = std::filesystem;

struct SlurmArgs {
  std::string file, output, partition, time_limit;
  int tasks = 1, cpus = 1;
  bool submit = false, force = false;
};

void slurm_command(const SlurmArgs& args) {
  const study::StudyFile file = study::load_study_file(args.file);
  study::check_cases(file);
  const bool replace = check_output_folder({args.output, args.force, {}, study::input_files(file)});
  study::SlurmJobRequest request;
  request.wifislam_binary = study::own_binary();
  request.study_file = fs::absolute(args.file).lexically_normal();
  request.tasks = args.tasks;
  request.cpus_per_task = args.cpus;
  request.partition = args.partition;
  request.time_limit = args.time_limit;
  const fs::path folder = absolute_folder(args.output);
  const study::SlurmJobFiles files = study::slurm_job_files(file, request, folder);
  study::write_slurm_job(folder, replace, files);
  fmt::print("wrote {0}/study.sbatch ({1} tasks) and {0}/merge.sbatch\n", folder.string(),
             args.tasks);
  if (!args.submit) {
    fmt::print(
        "submit: cd {} && J=$(sbatch --parsable study.sbatch) && sbatch "
        "--dependency=afterok:$J merge.sbatch\n",
        shell_quoted(folder.string()));
    return;
  }
  const study::SubmittedSlurmJob job = study::submit_slurm_job(folder, files);
  fmt::print("submitted array job {} and merge job {}; merged database: {}/{}\n", job.array_id,
             job.merge_id, folder.string(), files.merged_database.string());
}

}  // namespace

void add_study_slurm_command(CLI::App* app) {
  auto args = std::make_shared<SlurmArgs>();
  CLI::App* slurm = app->add_subcommand(
      "slurm",
      "Write a Slurm job array (one shard per task) and a dependent merge job for a study;\n"
      "--submit also submits both with sbatch");
  slurm->add_option("file", args->file, "Study file (YAML)")->required()->check(kNonEmptyInput);
  slurm->add_option("--tasks", args->tasks, "Array tasks = shards")
      ->required()
      ->check(CLI::Range(1, 100000));
  slurm->add_option("--cpus-per-task", args->cpus, "CPUs per task (the shard's --jobs)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1024));
  slurm->add_option("--partition", args->partition, "Slurm partition (default: the cluster's)")
      ->check(cli::kSlurmPartition);
  slurm->add_option("--time", args->time_limit, "Time limit per task, e.g. 02:00:00")
      ->check(cli::kSlurmTime);
  slurm
      ->add_option("-o,--output", args->output,
                   "Job folder: study.sbatch, merge.sbatch, shards/, logs/, and the merged\n"
                   "database once the merge job ran. On a cluster, a path every node sees")
      ->required();
  slurm->add_flag("--submit", args->submit, "Submit the array, then the merge (afterok)");
  slurm->add_flag("--force", args->force, "Replace an existing job folder of this tool");
  slurm->callback([args] { slurm_command(*args); });
}

}  // namespace wifislam::cli
