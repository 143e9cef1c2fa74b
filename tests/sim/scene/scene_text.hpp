#pragma once
// Scene files written as text in a test: the ParseError one must raise, and a one-place edit of
// a valid scene into a bad one.

#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "sim/scene/scene_loader.hpp"

namespace wifislam::sim::test {

/// Loads `yaml` (as the file `source`) and returns the ParseError it must raise.
inline ParseError expect_parse_error(const std::string& yaml, const std::string& source) {
  try {
    scene::load_scene_yaml(yaml, source);
  } catch (const ParseError& e) {
    return e;
  }
  ADD_FAILURE() << "no ParseError for:\n" << yaml;
  return ParseError("", "", "");
}

/// `text` with the first `from` replaced by `to`; fails the test when `from` is not there.
inline std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

}  // namespace wifislam::sim::test
