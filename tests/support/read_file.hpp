#pragma once
// The one way a test reads a whole file (bytes as they are). A file that cannot be opened fails
// the test that asked for it, so two missing files never compare equal as two empty ones.

#include <gtest/gtest.h>

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
/// empty when it cannot be opened, without failing the test.
inline std::string read_file_if_present(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace wifislam::test
