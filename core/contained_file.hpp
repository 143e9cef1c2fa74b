#pragma once
// A file another program wrote, checked before anything of ours reads it: it must lie below a
// folder with no symbolic link anywhere on its path (the folder itself included), and be a regular
// file. An external system's declared outputs are read this way (interop/external_outputs.hpp): a
// link to /etc/passwd or to the dataset's ground truth must not be imported as the system's
// output. Read it by its path only while nothing can change it (the program has ended).

#include <filesystem>
#include <string>

namespace wifislam {

/// What opening `root` and each folder of `relative` without following a link (openat,
/// O_NOFOLLOW) found about its last part.
struct ContainedFile {
  enum class State { kRegularFile, kMissing, kRefused } state = State::kMissing;
  std::string problem;  // kRefused: a symbolic link (and where), not a folder, not a regular file
};
ContainedFile inspect_file_below(const std::filesystem::path& root,
                                 const std::filesystem::path& relative);

/// The same, thrown: ParseError naming `root`/`relative` and what is wrong (missing included).
/// `relative` must be relative and free of "..".
void check_regular_file_below(const std::filesystem::path& root,
                              const std::filesystem::path& relative);

}  // namespace wifislam
