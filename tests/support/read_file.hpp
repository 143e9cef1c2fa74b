#pragma once
// The one way a test reads a whole file (bytes as they are). A file that cannot be opened fails
// the test that asked for it, so two missing files never compare equal as two empty ones.

#include <fcntl.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace wifislam::test {

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    ADD_FAILURE() << "cannot read " << path;
    return {};
  }
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// For a file that may vanish while the test reads it (a /proc entry of a process that exits):
/// empty when it cannot be opened or read, without failing the test. A /proc file opened before
/// its process exits fails its read with ESRCH, which libstdc++'s stream buffer throws whatever
/// the stream's exception mask says; plain read(2) reports it as an error to treat as "gone".
inline std::string read_file_if_present(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return {};
  std::string bytes;
  char buffer[4096];
  for (;;) {
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) bytes.clear();  // vanished mid-read: as if it had never been there
    if (got <= 0) break;
    bytes.append(buffer, static_cast<std::size_t>(got));
  }
  ::close(fd);
  return bytes;
}

}  // namespace wifislam::test
