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
  std::filesystem::path merged_database;   // relative to the folder
};

/// The two scripts for a folder at `folder` (absolute; where the scripts will live).
SlurmJobFiles slurm_job_files(const StudyFile& study, const SlurmJobRequest& request,
                              const std::filesystem::path& folder);

/// Writes the job folder (the two scripts, shards/ and logs/) atomically; `replace` as
/// core/output_folder.hpp's check_output_folder decided.
void write_slurm_job(const std::filesystem::path& folder, bool replace, const SlurmJobFiles& files);

struct SubmittedSlurmJob {
  std::string array_id, merge_id;
};

/// Submits the folder's array job with sbatch, then its merge job to start when every task has
/// succeeded (afterok). Throws EnvironmentError with sbatch's output when it fails.
SubmittedSlurmJob submit_slurm_job(const std::filesystem::path& folder);

/// The running wifislam binary (/proc/self/exe, absolute), for the job scripts.
std::filesystem::path own_binary();

}  // namespace wifislam::study
