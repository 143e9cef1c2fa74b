// `wifislam generate` and `wifislam check` as a user runs them: bad inputs give a clear error and
// a non-zero exit, and nothing is written.
#include <gtest/gtest.h>

#include "core/dataset_format.hpp"
#include "tests/sim/generate/test_scene.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"

namespace wifislam::sim {
namespace {

namespace fs = std::filesystem;

class GenerateCli : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_ = test::fresh_folder("scratch");
    fs::create_directories(scratch_);
    scene_ = scratch_ / "small_loop.yaml";
    test::write_text(scene_, test::kSmallSceneYaml);
  }
  void TearDown() override { fs::remove_all(scratch_); }
  // A short dataset to damage.
  fs::path make_dataset(const std::string& name) {
    const fs::path dir = scratch_ / name;
    const test::CliResult r =
        test::run_wifislam("generate " + scene_.string() + " -o " + dir.string() +
                               " --fps 5 --max-frames 12 --threads 2 -q",
                           scratch_);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return dir;
  }
  fs::path scratch_, scene_;
};

TEST_F(GenerateCli, GeneratesADatasetThatCheckAccepts) {
  const fs::path dir = make_dataset("ok");
  const test::CliResult r = test::run_wifislam("check " + dir.string(), scratch_);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("frames 12"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("all files match"), std::string::npos) << r.out;
}

TEST_F(GenerateCli, HelpExplainsHowToLowerTheFrameRate) {
  const test::CliResult r = test::run_wifislam("generate --help", scratch_);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("--fps"), std::string::npos);
  EXPECT_NE(r.out.find("fewer frames"), std::string::npos) << r.out;
}

TEST_F(GenerateCli, BadSceneFailsAndWritesNothing) {
  const fs::path bad = scratch_ / "bad.yaml";
  std::string yaml = test::kSmallSceneYaml;
  yaml.replace(yaml.find("width_m: 2.0"), 12, "widht_m: 2.0");
  test::write_text(bad, yaml);
  const fs::path out = scratch_ / "never";
  const test::CliResult r =
      test::run_wifislam("generate " + bad.string() + " -o " + out.string(), scratch_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.yaml"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("widht_m"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
}

// A dataset of no frames is one `check` refuses: --max-frames 0 is refused before any work.
TEST_F(GenerateCli, ZeroMaxFramesIsRefusedNotADatasetCheckRefuses) {
  for (const std::string command : {"generate", "compare"}) {
    const fs::path out = scratch_ / ("zero_" + command);
    const test::CliResult r = test::run_wifislam(
        command + " " + scene_.string() + " -o " + out.string() + " --max-frames 0", scratch_);
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find("--max-frames"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << command;
    EXPECT_FALSE(fs::exists(out.string() + ".partial")) << command;
  }
}

TEST_F(GenerateCli, ExistingOutputIsKeptUnlessForced) {
  // A folder of the user's is never replaced, --force or not.
  const fs::path mine = scratch_ / "existing";
  fs::create_directories(mine);
  test::write_text(mine / "keep.txt", "mine");
  for (const char* force : {"", " --force"}) {
    const test::CliResult r = test::run_wifislam(
        "generate " + scene_.string() + " -o " + mine.string() + " --max-frames 3 -q" + force,
        scratch_);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("does not look like wifislam output"), std::string::npos) << r.err;
    EXPECT_EQ(test::read_file(mine / "keep.txt"), "mine");
  }
  // A dataset is replaced with --force only.
  const fs::path out = make_dataset("dataset");
  const std::string manifest = test::read_file(out / dataset::kManifest);
  test::CliResult r = test::run_wifislam(
      "generate " + scene_.string() + " -o " + out.string() + " --max-frames 3", scratch_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
  EXPECT_EQ(test::read_file(out / dataset::kManifest), manifest);
  r = test::run_wifislam(
      "generate " + scene_.string() + " -o " + out.string() + " --max-frames 3 --force -q",
      scratch_);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(test::read_file(out / dataset::kManifest), manifest);
}

// Each damage: a non-zero exit, a message naming the file, and the folder left as it was.
void expect_check_fails(const fs::path& dir, const fs::path& scratch, const std::string& file,
                        const std::string& extra_args = "") {
  const auto before = test::listing(dir);
  const test::CliResult r = test::run_wifislam("check " + dir.string() + " " + extra_args, scratch);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  EXPECT_EQ(test::listing(dir), before);
}

TEST_F(GenerateCli, TruncatedGroundTruthIsAClearError) {
  const fs::path dir = make_dataset("gt");
  const std::string gt = test::read_file(dir / dataset::kGroundTruth);
  test::write_text(dir / dataset::kGroundTruth, gt.substr(0, gt.size() - 15));
  expect_check_fails(dir, scratch_, "groundtruth.txt:");
  expect_check_fails(dir, scratch_, "groundtruth.txt:", "--no-verify");
}

TEST_F(GenerateCli, MissingPngIsAClearError) {
  const fs::path dir = make_dataset("png");
  fs::remove(dir / "rgb" / "1700000001.200000.png");  // frame 6 on the default time origin
  expect_check_fails(dir, scratch_, "rgb/1700000001.200000.png");
  expect_check_fails(dir, scratch_, "associations.txt:7", "--no-verify");
}

TEST_F(GenerateCli, MalformedWifiRowIsAClearError) {
  const fs::path dir = make_dataset("wifi");
  std::string wifi = test::read_file(dir / dataset::kWifi);
  const auto second_line = wifi.find('\n') + 1;
  wifi.replace(wifi.find(',', wifi.find(',', second_line) + 1) + 1, 2, "zz");  // break a BSSID
  test::write_text(dir / dataset::kWifi, wifi);
  expect_check_fails(dir, scratch_, "wifi.csv");  // manifest mismatch
  expect_check_fails(dir, scratch_, "wifi.csv:2", "--no-verify");
}

TEST_F(GenerateCli, ManifestMismatchIsAClearError) {
  const fs::path dir = make_dataset("manifest");
  test::write_text(dir / dataset::kOdometry,
                   test::read_file(dir / dataset::kOdometry) + "# edit\n");
  expect_check_fails(dir, scratch_, "odometry.txt");
  const test::CliResult r = test::run_wifislam("check " + dir.string(), scratch_);
  EXPECT_NE(r.err.find("manifest mismatch"), std::string::npos) << r.err;
  EXPECT_EQ(test::run_wifislam("check " + dir.string() + " --no-verify", scratch_).exit_code, 0);
}

// A scene without access points is a legitimate study case (no Wi-Fi): its scans hear nothing,
// which wifi.csv (one row per reading) cannot show, so the manifest counts the scans the file
// holds and the silent ones apart; `check` accepts the dataset, vanilla SLAM runs on it and the
// Wi-Fi variant refuses it with a message that says why.
TEST_F(GenerateCli, ZeroAccessPointsGiveADatasetCheckAcceptsVanillaRunsAndWifiRefuses) {
  std::string yaml = test::kSmallSceneYaml;
  const std::string aps = "access_points: {placement: rooms, count: 6}";
  yaml.replace(yaml.find(aps), aps.size(), "access_points: {placement: rooms, count: 0}");
  const fs::path scene = scratch_ / "no_aps.yaml";
  test::write_text(scene, yaml);
  const fs::path dataset = scratch_ / "no_aps";
  const test::CliResult generated =
      test::run_wifislam("generate " + scene.string() + " -o " + dataset.string() +
                             " --fps 2 --max-frames 40 --threads 2 -q",
                         scratch_);
  ASSERT_EQ(generated.exit_code, 0) << generated.err;
  const std::string manifest = test::read_file(dataset / dataset::kManifest);
  EXPECT_NE(manifest.find("\"wifi_scans\": 0"), std::string::npos) << manifest;
  EXPECT_EQ(manifest.find("\"wifi_scans_that_heard_nothing\": 0"), std::string::npos)
      << "the route should pause and scan within 40 frames:\n"
      << manifest;

  const test::CliResult checked = test::run_wifislam("check " + dataset.string(), scratch_);
  EXPECT_EQ(checked.exit_code, 0) << checked.err;
  const test::CliResult vanilla = test::run_wifislam(
      "slam " + dataset.string() + " -o " + (scratch_ / "vanilla").string(), scratch_);
  EXPECT_EQ(vanilla.exit_code, 0) << vanilla.err;
  EXPECT_TRUE(fs::is_regular_file(scratch_ / "vanilla" / "trajectory.txt"));
  const test::CliResult wifi = test::run_wifislam(
      "slam " + dataset.string() + " --wifi -o " + (scratch_ / "wifi").string(), scratch_);
  EXPECT_EQ(wifi.exit_code, 2) << wifi.err;
  EXPECT_NE(wifi.err.find("without a scan"), std::string::npos) << wifi.err;
  EXPECT_FALSE(fs::exists(scratch_ / "wifi"));
}

}  // namespace
}  // namespace wifislam::sim
