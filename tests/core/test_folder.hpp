#pragma once
// A fresh temporary folder per test (tests/support/scratch_folder.hpp), and files written into it.

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/read_file.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::test {

inline std::filesystem::path fresh_folder(const std::string& name) { return scratch_folder(name); }

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

}  // namespace wifislam::test
