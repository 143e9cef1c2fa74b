#include "study/slurm_job.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cstdio>

#include <fmt/format.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "core/shell_quoted.hpp"

namespace wifislam::study {

namespace {

std::string sh(const std::string& text) { return shell_quoted(text); }

/// Runs `command` and returns its standard output; throws naming it when it fails.
std::string run_capturing(const std::string& command) {
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) throw EnvironmentError("cannot run: " + command);
  std::string out;
  char buffer[4096];
  while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
  const int status = ::pclose(pipe);
  if (status != 0) {
    while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
    // The shell's 127: no sbatch here, a missing facility (exit 4) as OpenGL's would be. Any
    // other failure is sbatch's own refusal: an external program that failed (exit 5).
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127) {
      throw EnvironmentError(
          "sbatch: not found; --submit needs a Slurm submit host (the job scripts are written: "
          "submit them with the line printed without --submit)");
    }
    throw ExternalSystemError(
        fmt::format("`{}` failed ({}): {}", command,
                    WIFEXITED(status) ? fmt::format("exit status {}", WEXITSTATUS(status))
                                      : fmt::format("killed by signal {}", WTERMSIG(status)),
                    out));
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  return out;
}

std::string job_name(const std::string& name) {
  std::string out = "wifislam-";
  for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  return out;
}

void check_job(int tasks, const std::filesystem::path& folder) {
  if (tasks < 1 || tasks > 100000) {
    throw InvalidInputError(fmt::format("--tasks {}: expected 1 to 100000", tasks));
  }
  if (folder.string().find_first_of(" \t\n") != std::string::npos) {
    // #SBATCH --output takes the rest of its line as the path: it cannot be quoted.
    throw InvalidInputError(folder.string() + ": a Slurm job folder's path may not contain spaces");
  }
}

std::string optional_lines(const std::string& partition, const std::string& time_limit) {
  std::string lines;
  if (!partition.empty()) lines += "#SBATCH --partition=" + partition + "\n";
  if (!time_limit.empty()) lines += "#SBATCH --time=" + time_limit + "\n";
  return lines;
}

}  // namespace

SlurmJobFiles slurm_array_files(const SlurmArrayJob& job, const std::filesystem::path& folder) {
  check_job(job.tasks, folder);
  SlurmJobFiles files;
  files.array_file = job.array_file;
  files.final_file = job.final_file;
  const std::string dir = folder.string();
  const std::string optional = optional_lines(job.partition, job.time_limit);
  files.array_script = fmt::format(
      "#!/bin/bash\n"
      "# {what}\n"
      "# Submit: sbatch {array}; then, with its job id J: sbatch --dependency=afterok:J {final}\n"
      "#SBATCH --job-name={job}\n"
      "#SBATCH --array=0-{last}\n"
      "#SBATCH --cpus-per-task={cpus}\n"
      "#SBATCH --output={dir}/logs/{log}\n"
      "{optional}"
      "set -euo pipefail\n"
      "exec {command}\n",
      fmt::arg("what", job.what), fmt::arg("array", job.array_file),
      fmt::arg("final", job.final_file), fmt::arg("job", job_name(job.name)),
      fmt::arg("last", job.tasks - 1), fmt::arg("cpus", job.cpus_per_task), fmt::arg("dir", dir),
      fmt::arg("log", job.task_log), fmt::arg("optional", optional),
      fmt::arg("command", job.task_command));
  files.merge_script = fmt::format(
      "#!/bin/bash\n"
      "# {what}\n"
      "#SBATCH --job-name={job}{suffix}\n"
      "#SBATCH --output={dir}/logs/{log}\n"
      "{optional}"
      "set -euo pipefail\n"
      "exec {command}\n",
      fmt::arg("what", job.final_what), fmt::arg("job", job_name(job.name)),
      fmt::arg("suffix", job.final_job_suffix), fmt::arg("dir", dir),
      fmt::arg("log", job.final_log), fmt::arg("optional", optional),
      fmt::arg("command", job.final_command));
  return files;
}

SlurmJobFiles slurm_job_files(const StudyFile& study, const SlurmJobRequest& request,
                              const std::filesystem::path& folder) {
  const std::string dir_q = sh(folder.string());
  SlurmArrayJob job;
  job.name = study.name;
  job.what = fmt::format("wifislam study '{}': {} cases in {} shards, one per array task.",
                         study.name, study.cases.size(), request.tasks);
  job.tasks = request.tasks;
  job.cpus_per_task = request.cpus_per_task;
  job.partition = request.partition;
  job.time_limit = request.time_limit;
  job.task_command = fmt::format(
      "{} study run {} --shard \"${{SLURM_ARRAY_TASK_ID}}/{}\" \\\n  --jobs {} -o "
      "{}/shards/shard-\"${{SLURM_ARRAY_TASK_ID}}\".sqlite",
      sh(request.wifislam_binary.string()), sh(request.study_file.string()), request.tasks,
      request.cpus_per_task, dir_q);
  const std::filesystem::path merged = column_name(study.name) + ".sqlite";
  std::string shards;
  for (int i = 0; i < request.tasks; ++i) {
    shards += fmt::format(" \\\n  {}/shards/shard-{}.sqlite", dir_q, i);
  }
  job.final_what = fmt::format("Unions the {} shard databases of study '{}' into {}.",
                               request.tasks, study.name, merged.string());
  job.final_command =
      fmt::format("{} study merge{} \\\n  --force -o {}/{}", sh(request.wifislam_binary.string()),
                  shards, dir_q, merged.string());
  job.array_file = "study.sbatch";
  job.final_file = "merge.sbatch";
  job.task_log = "shard-%a.log";
  job.final_log = "merge.log";
  job.final_job_suffix = "-merge";
  SlurmJobFiles files = slurm_array_files(job, folder);
  files.merged_database = merged;
  return files;
}

void write_slurm_job(const std::filesystem::path& folder, bool replace,
                     const SlurmJobFiles& files) {
  AtomicDirectory out(folder, replace);
  write_file_atomic(out.staging_path() / files.array_file, files.array_script);
  write_file_atomic(out.staging_path() / files.final_file, files.merge_script);
  std::filesystem::create_directories(out.staging_path() / "shards");
  std::filesystem::create_directories(out.staging_path() / "logs");
  out.commit();
}

SubmittedSlurmJob submit_slurm_job(const std::filesystem::path& folder,
                                   const SlurmJobFiles& files) {
  SubmittedSlurmJob job;
  job.array_id = run_capturing(
      fmt::format("sbatch --parsable {} 2>&1", sh((folder / files.array_file).string())));
  job.merge_id = run_capturing(fmt::format("sbatch --parsable --dependency=afterok:{} {} 2>&1",
                                           job.array_id, sh((folder / files.final_file).string())));
  return job;
}

std::filesystem::path own_binary() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw EnvironmentError("cannot find the wifislam binary (/proc/self/exe)");
  return self;
}

}  // namespace wifislam::study
