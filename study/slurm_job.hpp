#pragma once
// A study on a Slurm cluster: a job array whose task SLURM_ARRAY_TASK_ID runs shard
// SLURM_ARRAY_TASK_ID/N of the study into its own database, and a merge job that starts when
// every task has succeeded (afterok) and unions the shards into one database.
//
// Folder written (the paths in the scripts are absolute, so they run from any directory of a
// cluster whose nodes share the file system):
//   study.sbatch       the array job (sbatch study.sbatch)
//   merge.sbatch       the merge job (sbatch --dependency=afterok:<array id> merge.sbatch)
//   shards/            shard-<i>.sqlite, one per task (a resubmitted task resumes its shard)
//   logs/              one log per task and one for the merge
//   <study name>.sqlite  the merged database, once the merge job has run

#include <filesystem>
#include <string>

#include "study/study_file.hpp"

namespace wifislam::study {

struct SlurmJobRequest {
  std::filesystem::path wifislam_binary;  // absolute
  std::filesystem::path study_file;       // absolute
  int tasks = 1;
  int cpus_per_task = 1;   // also the shard's --jobs
  std::string partition;   // empty: the cluster's default
  std::string time_limit;  // empty: the partition's default (e.g. "02:00:00")
};

struct SlurmJobFiles {
  std::string array_script, merge_script;  // their text
  /// Their file names in the job folder: the array job's, and the job that runs once every task
  /// has succeeded.
  std::string array_file = "study.sbatch", final_file = "merge.sbatch";
  std::filesystem::path merged_database;  // relative to the folder (a study's)
};

/// The two scripts for a folder at `folder` (absolute; where the scripts will live).
SlurmJobFiles slurm_job_files(const StudyFile& study, const SlurmJobRequest& request,
                              const std::filesystem::path& folder);

/// Any job array and its final job: `tasks` tasks each run `task_command` (a shell line in which
/// "${SLURM_ARRAY_TASK_ID}" is the task's index), then `final_command` runs once every task has
/// succeeded (afterok). Logs go to <folder>/logs/. `wifislam paper --slurm` is one.
struct SlurmArrayJob {
  std::string name;        // the job's name (letters, digits and '-' are kept)
  std::string what;        // the array script's first comment
  std::string final_what;  // the final script's first comment
  int tasks = 1, cpus_per_task = 1;
  std::string partition, time_limit;  // empty: the cluster's defaults
  std::string task_command, final_command;
  std::string array_file, final_file;                             // file names in the job folder
  std::string task_log = "task-%a.log", final_log = "final.log";  // under logs/
  std::string final_job_suffix = "-final";  // the final job's name: the job's + this
};
SlurmJobFiles slurm_array_files(const SlurmArrayJob& job, const std::filesystem::path& folder);

/// Writes the job folder (the two scripts, shards/ and logs/) atomically; `replace` as
/// core/output_folder.hpp's check_output_folder decided.
void write_slurm_job(const std::filesystem::path& folder, bool replace, const SlurmJobFiles& files);

struct SubmittedSlurmJob {
  std::string array_id, merge_id;
};

/// Submits the folder's array job with sbatch, then its final job to start when every task has
/// succeeded (afterok). Throws EnvironmentError with sbatch's output when it fails.
SubmittedSlurmJob submit_slurm_job(const std::filesystem::path& folder,
                                   const SlurmJobFiles& files = {});

/// The running wifislam binary (/proc/self/exe, absolute), for the job scripts.
std::filesystem::path own_binary();

}  // namespace wifislam::study
