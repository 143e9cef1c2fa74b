#include "study/slurm_job.hpp"

#include <unistd.h>

#include <cctype>
#include <cstdio>

#include <fmt/format.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"

namespace wifislam::study {

namespace {

/// Single-quoted for the shell.
std::string sh(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// Runs `command` and returns its standard output; throws naming it when it fails.
std::string run_capturing(const std::string& command) {
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) throw EnvironmentError("cannot run: " + command);
  std::string out;
  char buffer[4096];
  while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
  const int status = ::pclose(pipe);
  if (status != 0) {
    throw EnvironmentError(fmt::format("`{}` failed (status {}): {}", command, status, out));
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  return out;
}

std::string job_name(const StudyFile& study) {
  std::string name = "wifislam-";
  for (char c : study.name) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  return name;
}

}  // namespace

SlurmJobFiles slurm_job_files(const StudyFile& study, const SlurmJobRequest& request,
                              const std::filesystem::path& folder) {
  if (request.tasks < 1 || request.tasks > 100000) {
    throw InvalidInputError(fmt::format("--tasks {}: expected 1 to 100000", request.tasks));
  }
  if (folder.string().find_first_of(" \t\n") != std::string::npos) {
    // #SBATCH --output takes the rest of its line as the path: it cannot be quoted.
    throw InvalidInputError(folder.string() + ": a Slurm job folder's path may not contain spaces");
  }
  SlurmJobFiles files;
  files.merged_database = column_name(study.name) + ".sqlite";
  const std::string dir = folder.string();
  std::string optional_lines;
  if (!request.partition.empty())
    optional_lines += "#SBATCH --partition=" + request.partition + "\n";
  if (!request.time_limit.empty()) optional_lines += "#SBATCH --time=" + request.time_limit + "\n";
  files.array_script = fmt::format(
      "#!/bin/bash\n"
      "# wifislam study '{name}': {cases} cases in {tasks} shards, one per array task.\n"
      "# Submit: sbatch study.sbatch; then, with its job id J: sbatch --dependency=afterok:J "
      "merge.sbatch\n"
      "#SBATCH --job-name={job}\n"
      "#SBATCH --array=0-{last}\n"
      "#SBATCH --cpus-per-task={cpus}\n"
      "#SBATCH --output={dir}/logs/shard-%a.log\n"
      "{optional}"
      "set -euo pipefail\n"
      "exec {bin} study run {study} --shard \"${{SLURM_ARRAY_TASK_ID}}/{tasks}\" \\\n"
      "  --jobs {cpus} -o {dir_q}/shards/shard-\"${{SLURM_ARRAY_TASK_ID}}\".sqlite\n",
      fmt::arg("name", study.name), fmt::arg("cases", study.cases.size()),
      fmt::arg("tasks", request.tasks), fmt::arg("job", job_name(study)),
      fmt::arg("last", request.tasks - 1), fmt::arg("cpus", request.cpus_per_task),
      fmt::arg("dir", dir), fmt::arg("optional", optional_lines),
      fmt::arg("bin", sh(request.wifislam_binary.string())),
      fmt::arg("study", sh(request.study_file.string())), fmt::arg("dir_q", sh(dir)));
  std::string shards;
  for (int i = 0; i < request.tasks; ++i) {
    shards += fmt::format(" \\\n  {}/shards/shard-{}.sqlite", sh(dir), i);
  }
  files.merge_script = fmt::format(
      "#!/bin/bash\n"
      "# Unions the {tasks} shard databases of study '{name}' into {merged}.\n"
      "#SBATCH --job-name={job}-merge\n"
      "#SBATCH --output={dir}/logs/merge.log\n"
      "{optional}"
      "set -euo pipefail\n"
      "exec {bin} study merge{shards} \\\n"
      "  --force -o {dir_q}/{merged}\n",
      fmt::arg("tasks", request.tasks), fmt::arg("name", study.name),
      fmt::arg("merged", files.merged_database.string()), fmt::arg("job", job_name(study)),
      fmt::arg("dir", dir), fmt::arg("optional", optional_lines),
      fmt::arg("bin", sh(request.wifislam_binary.string())), fmt::arg("shards", shards),
      fmt::arg("dir_q", sh(dir)));
  return files;
}

void write_slurm_job(const std::filesystem::path& folder, bool replace,
                     const SlurmJobFiles& files) {
  AtomicDirectory out(folder, replace);
  write_file_atomic(out.staging_path() / "study.sbatch", files.array_script);
  write_file_atomic(out.staging_path() / "merge.sbatch", files.merge_script);
  std::filesystem::create_directories(out.staging_path() / "shards");
  std::filesystem::create_directories(out.staging_path() / "logs");
  out.commit();
}

SubmittedSlurmJob submit_slurm_job(const std::filesystem::path& folder) {
  SubmittedSlurmJob job;
  job.array_id = run_capturing(
      fmt::format("sbatch --parsable {} 2>&1", sh((folder / "study.sbatch").string())));
  job.merge_id = run_capturing(fmt::format("sbatch --parsable --dependency=afterok:{} {} 2>&1",
                                           job.array_id, sh((folder / "merge.sbatch").string())));
  return job;
}

std::filesystem::path own_binary() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw EnvironmentError("cannot find the wifislam binary (/proc/self/exe)");
  return self;
}

}  // namespace wifislam::study
