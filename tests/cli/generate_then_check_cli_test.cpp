// Whatever `generate` writes, `check` accepts (issue 18): every shipped scene, scenes at the edges
// of the schema's ranges, and routes that turn back at a dead end, each generated for a few frames
// and read back whole as SLAM would.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"

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

/// Ground-truth poses of a dataset: time, x, y and yaw of the camera's optical axis.
struct TruthPose {
  double t, x, y, yaw;
};
std::vector<TruthPose> read_truth(const fs::path& dataset) {
  std::vector<TruthPose> poses;
  std::istringstream in(test::read_file(dataset / "groundtruth.txt"));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double t, x, y, z, qx, qy, qz, qw;
    fields >> t >> x >> y >> z >> qx >> qy >> qz >> qw;
    // The optical axis (camera z) in the world: the third column of the rotation.
    const double zx = 2 * (qx * qz + qw * qy), zy = 2 * (qy * qz - qw * qx);
    poses.push_back({t, x, y, std::atan2(zy, zx)});
  }
  return poses;
}

/// The longest run of consecutive poses with the position fixed and the yaw changing: the
/// robot turning on the spot (a pause keeps the yaw too). Returns its total turn in radians and
/// checks the yaw rate on the way.
double longest_turn_on_the_spot_rad(const std::vector<TruthPose>& poses, double max_yaw_rate) {
  double best = 0.0, run = 0.0;
  for (std::size_t i = 1; i < poses.size(); ++i) {
    const double moved = std::hypot(poses[i].x - poses[i - 1].x, poses[i].y - poses[i - 1].y);
    const double turned =
        std::abs(std::remainder(poses[i].yaw - poses[i - 1].yaw, 2 * std::numbers::pi));
    EXPECT_LE(turned / (poses[i].t - poses[i - 1].t), max_yaw_rate * 1.01) << poses[i].t;
    if (moved < 1e-6 && turned > 1e-6) {
      run += turned;
      best = std::max(best, run);
    } else if (moved >= 1e-6) {
      run = 0.0;
    }
  }
  return best;
}

/// A half turn on the spot at the yaw-rate limit (0.6 rad/s, the schema's default), as seen by
/// frames at `fps`: up to a frame interval of the turn at each end falls between a frame that
/// moves and one that does not.
void expect_half_turn_on_the_spot(const std::vector<TruthPose>& poses, double fps) {
  const double turn = longest_turn_on_the_spot_rad(poses, 0.6);
  EXPECT_GT(turn, std::numbers::pi - 2 * 0.6 / fps - 1e-3);
  EXPECT_LT(turn, std::numbers::pi + 1e-3);
}

// Issue 18: down a 20 m corridor and back passed `world` ("route length: 40.0 m") and failed in
// `generate` ("arc length does not increase at point 401").
TEST_F(GenerateThenCheck, DownAndBackTurnsOnTheSpotAtTheDeadEnd) {
  const fs::path scene = scratch_ / "down_and_back.yaml";
  test::write_file(scene, R"(version: 1
name: down_and_back
seed: 5
nodes:
  - {id: A, position_m: [0, 0]}
  - {id: B, position_m: [20, 0]}
corridors:
  - {id: only, from: A, to: B, width_m: 2.0}
access_points: {placement: random, count: 3}
route:
  nodes: [A, B, A]
  pause: {spacing_m: [3.0, 4.0], duration_s: 1.0}
sensors:
  camera: {width_px: 80, height_px: 60, fx_px: 65.6, fy_px: 65.6, cx_px: 39.5, cy_px: 29.5}
)");
  const auto world = wifislam("world " + scene.string());
  ASSERT_EQ(world.exit_code, 0) << world.err;
  EXPECT_NE(world.out.find("route length: 40.0 m"), std::string::npos) << world.out;
  EXPECT_NE(world.out.find("route time:"), std::string::npos) << world.out;
  const fs::path ds = generate_and_check(scene, "--fps 4");
  const auto poses = read_truth(ds);
  ASSERT_GT(poses.size(), 100u);
  // A half turn where the corridor ends, and back where it started.
  expect_half_turn_on_the_spot(poses, 4.0);
  // The last frame is at most a frame interval (0.5 m/s / 4 fps) short of the end.
  EXPECT_LT(std::hypot(poses.back().x, poses.back().y), 0.5 / 4 + 1e-3);
  double farthest = 0.0;
  for (const auto& p : poses) farthest = std::max(farthest, p.x);
  EXPECT_NEAR(farthest, 20.0, 1e-3);
  // Wheel odometry covers the whole run, the turn included.
  EXPECT_GT(test::read_file(ds / "odometry.txt").size(), 1000u);
}

// An L-shaped office walked into its end, back past the corner to the other end and out again:
// two dead ends turned at, a corner taken both ways.
TEST_F(GenerateThenCheck, RouteWithASpurTurnsAtEachDeadEnd) {
  const fs::path scene = scratch_ / "spur.yaml";
  test::write_file(scene, R"(version: 1
name: spur
seed: 6
nodes:
  - {id: A, position_m: [0, 0]}
  - {id: B, position_m: [8, 0]}
  - {id: C, position_m: [8, 5]}
corridors:
  - {id: long, from: A, to: B, width_m: 2.0}
  - {id: spur, from: B, to: C, width_m: 2.0}
access_points: {placement: random, count: 3}
route:
  nodes: [A, B, C, B, A, B, C]
  pause: {spacing_m: [3.0, 4.0], duration_s: 1.0}
sensors:
  camera: {width_px: 80, height_px: 60, fx_px: 65.6, fy_px: 65.6, cx_px: 39.5, cy_px: 29.5}
)");
  const auto world = wifislam("world " + scene.string());
  ASSERT_EQ(world.exit_code, 0) << world.err;
  const fs::path ds = generate_and_check(scene, "--fps 3");
  const auto poses = read_truth(ds);
  ASSERT_GT(poses.size(), 50u);
  expect_half_turn_on_the_spot(poses, 3.0);
  EXPECT_LT(std::hypot(poses.back().x - 8.0, poses.back().y - 5.0), 0.5 / 3 + 1e-3);
}

}  // namespace
}  // namespace wifislam
