#pragma once
// scenes/two_storey_office.yaml with its route on the upper level ("first"), written into a
// test's folder: the same building seen from its other floor (another-floor localisation, study
// place on an upper level).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "tests/support/read_file.hpp"

namespace wifislam::test {

/// Writes `dir`/upstairs.yaml and returns its path; fails the test if the shipped scene no
/// longer has the lines it replaces.
inline std::filesystem::path write_upstairs_two_storey_office(const std::filesystem::path& dir) {
  std::string upstairs = read_file(std::string(WIFISLAM_SCENES_DIR) + "/two_storey_office.yaml");
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"  nodes: [A, B]\n", "  nodes: [A1, B1]\n"},
        {"  level: ground\n", "  level: first\n"}}) {
    const auto at = upstairs.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) upstairs.replace(at, from.size(), to);
  }
  const std::filesystem::path path = dir / "upstairs.yaml";
  std::ofstream(path) << upstairs;
  return path;
}

}  // namespace wifislam::test
