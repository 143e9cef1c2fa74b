#pragma once
// Atomic writes: a crash or Ctrl-C never leaves a half-written file
// or folder that looks finished.

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/final_paths.hpp"

namespace wifislam {

/// Writes `contents` to `<path>.partial` then renames it over `path`. Refuses (InvalidInputError)
/// an existing `path` that is not a regular file: a folder, device or pipe is never replaced.
void write_file_atomic(const std::filesystem::path& path, std::string_view contents);

/// Several files that belong together (a result and its reports): every `<path>.partial` is
/// written before any is renamed into place, so a file that cannot be written (a missing folder,
/// a full disk) leaves none of them behind.
void write_files_atomic(
    const std::vector<std::pair<std::filesystem::path, std::string_view>>& files);

/// A folder under construction: everything is written into `<final>.partial/`, and `commit()`
/// renames it to `<final>`. Destroying an uncommitted AtomicDirectory removes the partial folder.
///
/// An existing `<final>` is replaced only if `overwrite`, and never when it is `/`, the current
/// directory or the home folder (or holds one of them), or does not look like this tool's output
/// and is not empty (core/output_folder.hpp); the staging folder carries the marker file that
/// makes it look like one. Commands check the rest of the rule (inputs, `--force`) with
/// `check_output_folder` first. Refusals are InvalidInputError; nothing is created then.
/// The staging folder is locked (flock) while it is written, so a second run into the same
/// folder is refused with a message saying so instead of deleting the first one's files.
class AtomicDirectory {
 public:
  AtomicDirectory(std::filesystem::path final_path, bool overwrite);
  ~AtomicDirectory();
  AtomicDirectory(const AtomicDirectory&) = delete;
  AtomicDirectory& operator=(const AtomicDirectory&) = delete;

  /// Where to write files now.
  const std::filesystem::path& staging_path() const { return staging_; }
  const std::filesystem::path& final_path() const { return final_; }
  /// For paths recorded in the files written now: where they will be after commit().
  FinalPaths final_paths() const { return {staging_, final_}; }
  void commit();

 private:
  std::filesystem::path final_, staging_;
  // The highest parent folder this object created for the output (empty: none); when the output
  // is not committed, the parents it created are removed again if they are empty.
  std::filesystem::path created_parent_;
  void remove_created_parents();
  bool overwrite_ = false, committed_ = false;
  int lock_fd_ = -1;  // the staging folder's lock, held until commit or destruction
};

/// SHA-256 of a file's bytes as lower-case hex (manifests).
std::string sha256_file_hex(const std::filesystem::path& path);
std::string sha256_hex(std::string_view bytes);

}  // namespace wifislam
