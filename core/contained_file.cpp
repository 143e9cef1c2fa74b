#include "core/contained_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"

namespace wifislam {

namespace {

namespace fs = std::filesystem;

class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }
  void reset(int fd) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = fd;
  }

 private:
  int fd_;
};

/// Why opening `name` (a folder or the file) under `at` failed, in words.
std::string why(int error, const std::string& name) {
  switch (error) {
    case ELOOP:
      return fmt::format("'{}' is a symbolic link; outputs must be files written there", name);
    case ENOTDIR:
      return fmt::format("'{}' is not a folder", name);
    case ENOENT:
      return "missing";
    default:
      return std::strerror(error);
  }
}

}  // namespace

ContainedFile inspect_file_below(const fs::path& root, const fs::path& relative) {
  const auto refused = [](std::string problem) {
    return ContainedFile{ContainedFile::State::kRefused, std::move(problem)};
  };
  const auto failed = [&](int error, const std::string& name) {
    return error == ENOENT ? ContainedFile{ContainedFile::State::kMissing, "missing"}
                           : refused(why(error, name));
  };
  if (relative.empty() || relative.is_absolute()) {
    return refused("expected a path relative to " + root.string());
  }
  Descriptor at(::open(root.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
  if (at.get() < 0) return failed(errno, root.string());
  std::vector<std::string> parts;
  for (const fs::path& part : relative) {
    if (part.empty() || part == ".") continue;
    if (part == "..") return refused("'..' leaves " + root.string());
    parts.push_back(part.string());
  }
  if (parts.empty()) return refused("names no file");
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    const int next =
        ::openat(at.get(), parts[i].c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (next < 0) {
      // O_DIRECTORY | O_NOFOLLOW on a link says ENOTDIR: look at the part itself to say which.
      const int error = errno;
      struct stat st {};
      if ((error == ENOTDIR || error == ELOOP) &&
          ::fstatat(at.get(), parts[i].c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0 &&
          S_ISLNK(st.st_mode)) {
        return refused(why(ELOOP, parts[i]));
      }
      return failed(error, parts[i]);
    }
    at.reset(next);
  }
  struct stat st {};
  if (::fstatat(at.get(), parts.back().c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0) {
    return failed(errno, parts.back());
  }
  if (S_ISLNK(st.st_mode)) return refused(why(ELOOP, parts.back()));
  if (!S_ISREG(st.st_mode)) {
    return refused("is not a regular file (a folder, a device or a pipe)");
  }
  return {ContainedFile::State::kRegularFile, ""};
}

void check_regular_file_below(const fs::path& root, const fs::path& relative) {
  const ContainedFile file = inspect_file_below(root, relative);
  if (file.state != ContainedFile::State::kRegularFile) {
    throw ParseError((root / relative).string(), "", file.problem);
  }
}

}  // namespace wifislam
