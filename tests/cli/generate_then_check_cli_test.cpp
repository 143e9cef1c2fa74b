// Whatever `generate` writes, `check` accepts (issue 18): every shipped scene and scenes at the
// edges of the schema's ranges, each generated for a few frames and read back whole as SLAM would.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/cli/cli_run.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;
using test::run_wifislam;

std::vector<std::string> shipped_scenes() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(WIFISLAM_SCENES_DIR)) {
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class GenerateThenCheck : public ::testing::Test {
 protected:
  void SetUp() override { scratch_ = test::scratch_folder(); }
  void TearDown() override { fs::remove_all(scratch_); }

  test::CliResult wifislam(const std::string& args) { return run_wifislam(args, scratch_); }

  /// Generates `scene` into a fresh folder with `options` and checks it; returns the folder.
  fs::path generate_and_check(const fs::path& scene, const std::string& options) {
    const fs::path out = scratch_ / ("ds_" + std::to_string(++runs_));
    const auto generated =
        wifislam("generate " + scene.string() + " -o " + out.string() + " -q " + options);
    EXPECT_EQ(generated.signal, 0) << generated.err;
    EXPECT_EQ(generated.exit_code, 0) << scene << ": " << generated.err;
    const auto checked = wifislam("check " + out.string());
    EXPECT_EQ(checked.exit_code, 0) << scene << ": " << checked.err;
    return out;
  }

  fs::path scratch_;
  int runs_ = 0;
};

class ShippedSceneGenerateThenCheck : public GenerateThenCheck,
                                      public ::testing::WithParamInterface<std::string> {};

// A few frames at a low frame rate keep this cheap; the world, the radio model, the pause at the
// start with its scans, the odometry and the files are those of the full run.
TEST_P(ShippedSceneGenerateThenCheck, CheckAcceptsWhatGenerateWrites) {
  const fs::path scene = fs::path(WIFISLAM_SCENES_DIR) / (GetParam() + ".yaml");
  const fs::path ds = generate_and_check(scene, "--fps 1 --max-frames 5");
  const auto checked = wifislam("check " + ds.string());
  EXPECT_NE(checked.out.find("frames 5,"), std::string::npos) << checked.out;
  EXPECT_NE(checked.out.find("checksums: all files match"), std::string::npos) << checked.out;
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShippedSceneGenerateThenCheck,
                         ::testing::ValuesIn(shipped_scenes()),
                         [](const auto& info) { return info.param; });

// The tiny loop with `from` replaced by `to`.
std::string tiny_loop_with(const std::string& from, const std::string& to) {
  std::string yaml = test::kTinyLoopYaml;
  const auto at = yaml.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) yaml.replace(at, from.size(), to);
  return yaml;
}

// Every number at the top of its range: the strongest transmitters, the widest shadowing and
// fading (RSSI that once came out above what the reader takes), the noisiest odometry.
TEST_F(GenerateThenCheck, ScenesAtTheEdgesOfTheSchemaGiveReadableDatasets) {
  const fs::path scene = scratch_ / "edges.yaml";
  test::write_file(
      scene,
      tiny_loop_with("radio: {environment: office}",
                     "radio: {environment: office, shadowing_sigma_db: 30, fast_fading_sigma_db: "
                     "30}\nsensors:\n  odometry: {noise_per_m: 1, noise_per_rad: 1}\n") +
          "\n");
  std::string yaml = test::read_file(scene);
  yaml.replace(yaml.find("access_points: {placement: random, count: 8}"),
               std::string("access_points: {placement: random, count: 8}").size(),
               "access_points: {placement: random, count: 8, tx_power_dbm: 36}");
  test::write_file(scene, yaml);
  const fs::path ds = generate_and_check(scene, "--fps 1 --max-frames 4 --no-images");
  EXPECT_EQ(test::read_file(ds / "odometry.txt").find("inf"), std::string::npos);
  EXPECT_EQ(test::read_file(ds / "odometry.txt").find("nan"), std::string::npos);
  // The longest pause the schema takes: the robot stands for an hour at the start.
  const fs::path still = scratch_ / "still.yaml";
  test::write_file(still, tiny_loop_with("duration_s: 1.0", "duration_s: 3600"));
  generate_and_check(still, "--fps 0.1 --max-frames 3 --no-images");
}

}  // namespace
}  // namespace wifislam
