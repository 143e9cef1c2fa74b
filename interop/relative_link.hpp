#pragma once
// The exports link to the dataset's images instead of copying them: relative symbolic links, so
// that the export and the dataset may move or be mounted together.

#include <filesystem>

namespace wifislam::interop {

/// A symbolic link at `at` (in the staging folder) to `target`, relative to where the link will
/// live after the staging folder's rename (`at_final`); the staging folder is the final folder's
/// sibling, so the link resolves from there too. IoError when the file system has no links.
void link_relative(const std::filesystem::path& target, const std::filesystem::path& at_final,
                   const std::filesystem::path& at);

}  // namespace wifislam::interop
