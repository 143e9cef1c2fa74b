#include "interop/relative_link.hpp"

#include <system_error>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/output_folder.hpp"

namespace wifislam::interop {

void link_relative(const std::filesystem::path& target, const std::filesystem::path& at_final,
                   const std::filesystem::path& at) {
  std::error_code link_error;
  std::filesystem::create_symlink(resolve_path(target).lexically_relative(at_final.parent_path()),
                                  at, link_error);
  if (link_error) {
    throw IoError(fmt::format(
        "{}: cannot create a link to {} ({}; the export needs a file system with symbolic links)",
        at.string(), target.string(), link_error.message()));
  }
}

}  // namespace wifislam::interop
