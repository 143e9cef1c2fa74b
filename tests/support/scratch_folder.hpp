#pragma once
// The one way a test gets a folder of its own: under the system's temporary folder, named for the
// running test, emptied when asked for, and removed when the test process exits if its tests
// passed. A failed test's files stay for a look; the next run of that test empties them. ctest
// runs each test in a process of its own, so "exit" is the end of the test.

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace wifislam::test {

namespace detail {

/// The folders handed out in this process. Constructed after GoogleTest's UnitTest (the first
/// folder is asked for while a test runs), so destroyed before it: the verdict is still there.
struct ScratchFolders {
  std::vector<std::filesystem::path> paths;
  ~ScratchFolders() {
    if (!::testing::UnitTest::GetInstance()->Passed()) return;
    for (const std::filesystem::path& path : paths) {
      std::error_code ignored;  // a test may have removed its folder itself
      std::filesystem::remove_all(path, ignored);
    }
  }
};

inline ScratchFolders& scratch_folders() {
  static ScratchFolders folders;
  return folders;
}

}  // namespace detail

/// `<tmp>/wifislam_<suite>_<test>_<pid>[_<tag>]`, empty (`<test>` is "setup" in SetUpTestSuite).
inline std::filesystem::path scratch_folder(const std::string& tag = "") {
  const ::testing::UnitTest& unit = *::testing::UnitTest::GetInstance();
  const ::testing::TestInfo* info = unit.current_test_info();
  // In SetUpTestSuite no test runs yet: the folder is the suite's ("<suite>_setup").
  const ::testing::TestSuite* suite = unit.current_test_suite();
  std::string name = "wifislam_" +
                     std::string(info    ? info->test_suite_name()
                                 : suite ? suite->name()
                                         : "suite") +
                     "_" + (info ? info->name() : "setup");
  name += "_" + std::to_string(::getpid());
  if (!tag.empty()) name += "_" + tag;  // last: a test may name the folder's suffix (".partial")
  // A parameterised test's names hold slashes ("Scenes/Suite", "Test/0"): one folder, not a tree.
  std::replace(name.begin(), name.end(), '/', '_');
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  detail::scratch_folders().paths.push_back(dir);
  return dir;
}

}  // namespace wifislam::test
