#pragma once
// Running the real `wifislam` binary as a user does, in a scratch folder of its own: the exit
// code (or the signal that ended it), stdout and stderr.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/read_file.hpp"
#include "tests/support/scratch_folder.hpp"
#include "tests/support/square_loop_scene.hpp"

namespace wifislam::test {

struct CliResult {
  int exit_code = -1;  // -1 when a signal ended the process
  int signal = 0;
  std::string out, err;
};

inline void write_file(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

/// Runs `wifislam <args>` through the shell, in `cwd`, after `prefix` (e.g. "ulimit -v 1000000;").
/// Output goes to files in `scratch`, which must not be a folder the command may change.
inline CliResult run_wifislam(const std::string& args, const std::filesystem::path& scratch,
                              const std::filesystem::path& cwd = {},
                              const std::string& prefix = "") {
  const std::filesystem::path out = scratch / "stdout.txt", err = scratch / "stderr.txt";
  std::string command = "(";
  if (!cwd.empty()) command += "cd '" + cwd.string() + "' && ";
  command += prefix + " exec " + std::string(WIFISLAM_BINARY) + " " + args + ") >'" + out.string() +
             "' 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  CliResult r;
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  // The shell reports a child killed by a signal as 128 + signal.
  if (r.exit_code > 128 && r.exit_code < 160) r.signal = r.exit_code - 128;
  r.out = test::read_file(out);
  r.err = test::read_file(err);
  return r;
}

/// Every path under `dir` with its size, sorted: a folder's contents before and after a command.
inline std::vector<std::string> listing(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    names.push_back(e.path().string() +
                    (e.is_regular_file() ? " " + std::to_string(e.file_size()) : "/"));
  }
  std::sort(names.begin(), names.end());
  return names;
}

/// A small square loop (7 x 5 m) with distinct walls; 12 frames at 2 fps give SLAM and eval a short
/// real run.
inline const std::string kTinyLoopYaml = square_loop_yaml(
    {.name = "cli_tiny_loop", .description = "Small square loop for command-line tests."});

/// The tiny loop's text with `from` replaced by `to` (which must occur in it).
inline std::string tiny_loop_yaml_with(const std::string& from, const std::string& to) {
  std::string yaml = kTinyLoopYaml;
  const auto at = yaml.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) yaml.replace(at, from.size(), to);
  return yaml;
}

/// Writes `dir / name`: the tiny loop with `from` replaced by `to` (which must occur in it).
inline std::filesystem::path tiny_loop_with(const std::filesystem::path& dir,
                                            const std::string& from, const std::string& to,
                                            const std::string& name) {
  const std::filesystem::path path = dir / name;
  write_file(path, tiny_loop_yaml_with(from, to));
  return path;
}

/// The tiny loop with 4 s pauses: long enough for a Wi-Fi scan, so Wi-Fi variants run too.
inline std::string tiny_wifi_loop_yaml() {
  return tiny_loop_yaml_with("duration_s: 1.0", "duration_s: 4.0");
}

/// Bad input as the README promises it: exit 2 (no signal), a message naming `where` (file,
/// line) and `what` (key, value), and no "internal error".
inline void expect_located_bad_input(const CliResult& r, const std::string& where,
                                     const std::string& what) {
  EXPECT_EQ(r.signal, 0) << r.err;
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(where), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
}

}  // namespace wifislam::test
