#pragma once
// Atomic writes (DESIGN.md, "Conventions"): a crash or Ctrl-C never leaves a half-written file
// or folder that looks finished.

#include <filesystem>
#include <string>
#include <string_view>

namespace wifislam {

/// Writes `contents` to `<path>.partial` then renames it over `path`.
void write_file_atomic(const std::filesystem::path& path, std::string_view contents);

/// A folder under construction: everything is written into `<final>.partial/`, and `commit()`
/// renames it to `<final>` (replacing an existing folder only if `overwrite`). Destroying an
/// uncommitted AtomicDirectory removes the partial folder.
class AtomicDirectory {
 public:
  AtomicDirectory(std::filesystem::path final_path, bool overwrite);
  ~AtomicDirectory();
  AtomicDirectory(const AtomicDirectory&) = delete;
  AtomicDirectory& operator=(const AtomicDirectory&) = delete;

  /// Where to write files now.
  const std::filesystem::path& staging_path() const { return staging_; }
  const std::filesystem::path& final_path() const { return final_; }
  void commit();

 private:
  std::filesystem::path final_, staging_;
  bool overwrite_ = false, committed_ = false;
};

/// SHA-256 of a file's bytes as lower-case hex (manifests).
std::string sha256_file_hex(const std::filesystem::path& path);
std::string sha256_hex(std::string_view bytes);

}  // namespace wifislam
