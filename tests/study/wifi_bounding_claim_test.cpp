// The paper's central claim ("RGBD SLAM performance": Wi-Fi "gets rid of all false loop closures"
// and lowers the trajectory error) on the twin-corridor scene of `wifislam demo`: two corridors
// 30 m apart that look alike (aliasing 1.0, scope position). At a low min_matches, vanilla
// RGBD-SLAM's random long-term candidates reach the other corridor and accept a false loop closure;
// the Wi-Fi variant only draws candidates from similar Wi-Fi clusters and accepts none.
//
// Two seeds (different textures, AP placements, noise and random draws) are pooled, so the claim is
// checked on more than one lucky draw. Also checks the comparison's files.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "apps/demo_scene.hpp"
#include "core/error.hpp"
#include "eval/study/comparison_study.hpp"
#include "sim/scene/scene_loader.hpp"

namespace wifislam::study {
namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// One comparison run (2 seeds x {vanilla, wifi}) checked in one test: ctest runs every test in a
/// process of its own, so splitting the checks would run the whole comparison once per check.
TEST(WifiBoundingClaim, WifiBoundingRemovesFalseLoopClosuresAndLowersTrajectoryError) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() /
                                    ("wifislam_claim_test_" + std::to_string(::getpid()));
  std::filesystem::remove_all(out);
  std::filesystem::create_directories(out);
  ComparisonOptions options;
  options.settings = {"min_matches=10"};
  options.seeds = 2;
  options.jobs = 2;
  options.plots = false;
  Scene scene = load_scene_yaml(cli::kDemoSceneYaml, "<demo scene>");
  scene.seed = 7;  // seeds 7 and 8 (the demo's)
  const ComparisonResult result = run_comparison({scene}, options, out);

  ASSERT_EQ(result.cases.size(), 4u);  // 2 seeds x {vanilla, wifi}
  std::int64_t vanilla_false = 0, wifi_false = 0, wifi_detected = 0;
  double vanilla_ate_m = 0, wifi_ate_m = 0;
  for (const ComparisonCase& c : result.cases) {
    const eval::RunEvaluation& e = c.evaluation;
    SCOPED_TRACE(c.run_dir.string());
    EXPECT_GT(e.frames_associated, 700);
    if (c.wifi) {
      wifi_false += e.false_positives;
      wifi_detected += e.loop_closures_detected;
      wifi_ate_m += e.ate_rmse_m;
      EXPECT_GT(e.wifi_clusters, 2);  // the two corridors and the hall are told apart
    } else {
      vanilla_false += e.false_positives;
      vanilla_ate_m += e.ate_rmse_m;
    }
  }
  EXPECT_GE(vanilla_false, 1) << "vanilla RGBD-SLAM should fall for the look-alike corridor";
  EXPECT_EQ(wifi_false, 0) << "of " << wifi_detected << " loop closures of the Wi-Fi variant";
  EXPECT_LT(wifi_ate_m, vanilla_ate_m);

  // The comparison's files: tables, one CSV row per run, every run folder with its evaluation.
  const std::string md = read_text(out / "comparison.md");
  EXPECT_NE(md.find("| scene | min_matches=10 Vanilla | min_matches=10 WiFi |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("| twin_corridors |"), std::string::npos);
  EXPECT_NE(md.find("False positive loop closures"), std::string::npos);
  const std::string csv = read_text(out / "comparison.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);  // header + 4 runs
  for (const ComparisonCase& c : result.cases) {
    EXPECT_TRUE(std::filesystem::exists(out / c.run_dir / "trajectory.txt"));
    EXPECT_TRUE(std::filesystem::exists(out / c.run_dir / "eval" / "metrics.json"));
    EXPECT_EQ(std::filesystem::exists(out / c.run_dir / "wifi_clusters.csv"), c.wifi);
  }
  std::filesystem::remove_all(out);
}

TEST(ComparisonSweep, RejectsAnUnknownKeyOrBadValues) {
  EXPECT_THROW(parse_sweep("min_matchez=10,20"), ParseError);
  EXPECT_THROW(parse_sweep("min_matches=10,,20"), ParseError);
  EXPECT_THROW(parse_sweep("min_matches=ten"), ParseError);
  const SweepAxis axis = parse_sweep("min_matches=10,15,20");
  EXPECT_EQ(axis.values, (std::vector<std::string>{"10", "15", "20"}));
}

}  // namespace
}  // namespace wifislam::study
