#pragma once
// Paths recorded inside a folder under construction (AtomicDirectory's `<final>.partial/`) that
// name places in that folder: run.json's command line, metrics.json's run folder, a comparison's
// evaluations. Recorded as they are while writing, they would name the staging folder, which is
// gone once the folder is committed; recorded through FinalPaths, they name where the files will
// be.

#include <filesystem>
#include <string>

namespace wifislam {

class FinalPaths {
 public:
  /// Nothing under construction: every path is recorded as given.
  FinalPaths() = default;
  /// Files written under `staging` will be under `final` (both made absolute).
  FinalPaths(const std::filesystem::path& staging, const std::filesystem::path& final);

  /// `path`, absolute, with the staging folder replaced by the final one when it lies in it;
  /// any other path as given.
  std::filesystem::path of(const std::filesystem::path& path) const;
  /// `text` (a message, a command line) with every mention of the staging folder replaced.
  std::string in_text(std::string text) const;

 private:
  std::filesystem::path staging_, final_;
};

}  // namespace wifislam
