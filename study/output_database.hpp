#pragma once
// The rules for the database file a study writes (`study run -o DB`, `study merge -o DB`): the
// one documented exception to "an existing output is replaced only with --force" is resuming a
// database of the same study; anything that is not a study database is never touched.

#include <filesystem>
#include <vector>

#include "study/study_file.hpp"

namespace wifislam::study {

/// For `study run`: a new file; the database of the same study (resumed); with `force`, a study
/// database of another study or build. Refuses, with InvalidInputError naming the file, anything
/// else, and an input of the command (core/output_folder.hpp's check_output_file). Removes
/// nothing: returns whether the run must replace the file, which ResultStore does once it holds
/// the database's lock and the cases have been checked (StudyRunOptions::replace_database).
bool check_run_database(const std::filesystem::path& path, const StudyFile& study, bool force,
                        const std::vector<std::filesystem::path>& inputs);

/// For `study merge`: a new file, or with `force` an existing study database; never a shard
/// being merged or a file that is not a study database. (merge_study_databases replaces it
/// holding its lock: not while a run writes it.)
void prepare_merged_database(const std::filesystem::path& path, bool force,
                             const std::vector<std::filesystem::path>& shards);

}  // namespace wifislam::study
