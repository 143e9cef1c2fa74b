// `wifislam slam` on a dataset folder takes the options that mean something there and refuses
// the ones that do not (issue 18): --max-frames stops early on datasets too, --fps and --seed
// are scene-input options, negative or non-finite numbers are refused, and an unfinished
// dataset (an interrupted `generate`) is refused unless --no-verify.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "tests/cli/shared_dataset.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;

class SlamInput : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_ = test::scratch_folder();
    scene_ = scratch_ / "tiny.yaml";
    test::write_file(scene_, test::kTinyLoopYaml);
    dataset_ = test::shared_dataset(test::kTinyLoopYaml, "--fps 2 --max-frames 12 --threads 2");
    ASSERT_FALSE(dataset_.empty()) << "wifislam generate failed";
  }
  void TearDown() override { fs::remove_all(scratch_); }
  test::CliResult wifislam(const std::string& args) { return test::run_wifislam(args, scratch_); }
  static int pose_lines(const fs::path& trajectory) {
    std::ifstream in(trajectory);
    int n = 0;
    for (std::string line; std::getline(in, line);) n += !line.empty() && line[0] != '#';
    return n;
  }
  fs::path scratch_, scene_, dataset_;
};

TEST_F(SlamInput, MaxFramesStopsADatasetRunEarly) {
  const fs::path run = scratch_ / "run";
  const auto r = wifislam("slam " + dataset_.string() + " --max-frames 4 -o " + run.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(pose_lines(run / "trajectory.txt"), 4);
  const auto all = wifislam("slam " + dataset_.string() + " -o " + (scratch_ / "all").string());
  ASSERT_EQ(all.exit_code, 0) << all.err;
  EXPECT_EQ(pose_lines(scratch_ / "all" / "trajectory.txt"), 12);
}

// The in-memory stream hands SLAM the Unix stamps a generated dataset holds (sensors.time_origin_s
// on route time), so a run on the scene and a run on its dataset are one run, to the byte.
TEST_F(SlamInput, ASceneAndItsGeneratedDatasetGiveTheSameRun) {
  const fs::path on_dataset = scratch_ / "on_dataset", on_scene = scratch_ / "on_scene";
  const auto d = wifislam("slam " + dataset_.string() + " -o " + on_dataset.string());
  ASSERT_EQ(d.exit_code, 0) << d.err;
  const auto s =
      wifislam("slam " + scene_.string() + " --fps 2 --max-frames 12 -o " + on_scene.string());
  ASSERT_EQ(s.exit_code, 0) << s.err;
  for (const char* file : {"trajectory.txt", "keyframes.txt", "graph.json", "loop_closures.csv"}) {
    const std::string a = test::read_file(on_dataset / file);
    EXPECT_FALSE(a.empty()) << file;
    EXPECT_EQ(a, test::read_file(on_scene / file)) << file;
  }
  std::ifstream trajectory(on_scene / "trajectory.txt");
  std::string line;
  while (std::getline(trajectory, line) && line.starts_with("#")) {
  }
  EXPECT_TRUE(line.starts_with("1700000000.000000 ")) << line;
}

TEST_F(SlamInput, FpsAndSeedOnADatasetAreRefusedNotIgnored) {
  for (const char* option : {"--fps 5", "--seed 3"}) {
    const fs::path run = scratch_ / "run";
    const auto r = wifislam("slam " + dataset_.string() + " " + option + " -o " + run.string());
    EXPECT_EQ(r.exit_code, 2) << option << ": " << r.err;
    // The option and its value, as given.
    EXPECT_NE(r.err.find(std::string(option) + ": applies to scene input only"), std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(run));
  }
}

TEST_F(SlamInput, NegativeOrNonFiniteNumbersAreRefused) {
  for (const char* option :
       {"--max-frames -3", "--max-frames 0", "--fps nan", "--fps -2", "--seed -1"}) {
    const fs::path run = scratch_ / "run";
    const auto r = wifislam("slam " + scene_.string() + " " + option + " -o " + run.string());
    EXPECT_NE(r.exit_code, 0) << option;
    EXPECT_EQ(r.signal, 0) << option;
    EXPECT_FALSE(fs::exists(run)) << option;
  }
}

TEST_F(SlamInput, AnUnfinishedDatasetIsRefusedUnlessNoVerify) {
  // What an interrupted generate leaves: the staging folder, marked, without its manifest.
  const fs::path partial = scratch_ / "ds.partial";
  fs::copy(dataset_, partial, fs::copy_options::recursive);
  fs::remove(partial / "manifest.json");
  ASSERT_TRUE(fs::exists(partial / ".wifislam-output"));
  const auto refused = wifislam("slam " + partial.string() + " -o " + (scratch_ / "r").string());
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("unfinished dataset"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(scratch_ / "r"));
  const auto read_anyway =
      wifislam("slam " + partial.string() + " --no-verify -o " + (scratch_ / "r").string());
  EXPECT_EQ(read_anyway.exit_code, 0) << read_anyway.err;
}

// A seed is what a scene file's `seed:` accepts, 0 .. 2^64 - 1; CLI11 alone would wrap -1 and
// 2^64 to 2^64 - 1.
TEST_F(SlamInput, SeedsOutsideTheSceneFilesRangeAreRefused) {
  for (const char* seed : {"-1", "18446744073709551616", "1e3", "+5"}) {
    const fs::path out = scratch_ / "gen";
    const auto r = wifislam("generate " + scene_.string() + " --seed " + seed +
                            " --max-frames 2 -q -o " + out.string());
    EXPECT_NE(r.exit_code, 0) << seed;
    EXPECT_NE(r.err.find("whole number from 0 to 18446744073709551615"), std::string::npos)
        << seed << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << seed;
  }
  const auto top = wifislam("generate " + scene_.string() +
                            " --seed 18446744073709551615 --max-frames 2 --fps 2 -q -o " +
                            (scratch_ / "top").string());
  EXPECT_EQ(top.exit_code, 0) << top.err;
}

}  // namespace
}  // namespace wifislam
