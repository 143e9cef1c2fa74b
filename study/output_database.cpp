#include "study/output_database.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "study/result_store.hpp"

namespace wifislam::study {

namespace fs = std::filesystem;

bool check_run_database(const fs::path& path, const StudyFile& study, bool force,
                        const std::vector<fs::path>& inputs) {
  check_output_file(path, inputs);
  std::error_code ec;
  if (!fs::exists(path, ec)) return false;
  const auto identity = ResultStore::read_identity(path);
  if (!identity) {
    throw InvalidInputError(fmt::format(
        "{}: exists and is not a study database; refusing to touch it (even with --force)",
        path.string()));
  }
  if (*identity == identity_of(study)) return false;  // resume
  if (!force) {
    throw InvalidInputError(fmt::format(
        "{}: a study database of study '{}' (another study file, or another build of wifislam); "
        "give --force to replace it, or another -o",
        path.string(), identity->name));
  }
  return true;
}

void prepare_merged_database(const fs::path& path, bool force,
                             const std::vector<fs::path>& shards) {
  check_output_file(path, shards);
  std::error_code ec;
  if (!fs::exists(path, ec)) return;
  if (!ResultStore::read_identity(path)) {
    throw InvalidInputError(path.string() +
                            ": exists and is not a study database; refusing to replace it (even "
                            "with --force)");
  }
  if (!force) throw InvalidInputError(path.string() + ": exists; give --force to replace it");
}

}  // namespace wifislam::study
