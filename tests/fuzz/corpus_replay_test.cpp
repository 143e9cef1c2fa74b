// Replays every committed fuzz input (fuzz/corpus/<target>, the minimised corpus; and
// fuzz/crashes/<target>, one reproducer per finding, kept after its fix) through the same entry
// points the libFuzzer drivers call. A reproducer that crashes, aborts or lets a non-wifislam
// exception escape fails here, in the suite CI runs, without clang or libFuzzer.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fuzz/fuzz_targets.hpp"
#include "tests/support/read_file.hpp"

namespace wifislam::fuzz {

// Test names and failure messages show the target's name, not its bytes.
void PrintTo(const Target& target, std::ostream* os) { *os << target.name; }

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> inputs_of(const std::string& target, const char* kind) {
  std::vector<fs::path> files;
  const fs::path dir = fs::path(WIFISLAM_FUZZ_DIR) / kind / target;
  if (!fs::is_directory(dir)) return files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().filename().string()[0] != '.') {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

class CorpusReplay : public ::testing::TestWithParam<Target> {};

TEST_P(CorpusReplay, EveryCommittedInputIsAcceptedOrRefusedWithOurErrors) {
  const Target& target = GetParam();
  const std::vector<fs::path> corpus = inputs_of(target.name, "corpus");
  // An empty corpus would make this test pass without running anything.
  ASSERT_GE(corpus.size(), 10u) << "fuzz/corpus/" << target.name << " is missing or nearly empty";
  std::vector<fs::path> all = corpus;
  for (const fs::path& crash : inputs_of(target.name, "crashes")) all.push_back(crash);
  for (const fs::path& input : all) {
    const std::string bytes = test::read_file(input);
    SCOPED_TRACE(input.string());
    EXPECT_NO_THROW(target.run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()));
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, CorpusReplay, ::testing::ValuesIn(targets()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace wifislam::fuzz
