// The paper's central claim ("RGBD SLAM performance": Wi-Fi "gets rid of all false loop closures"
// and lowers the trajectory error), end to end: generate -> SLAM vanilla and Wi-Fi -> eval.
//
// - On the c_hall twin (the paper's square loop of look-alike corridors, seed 1001, 3 fps, the
//   whole route), for RGBD-SLAM and for the ORB-SLAM-style front end at default settings: vanilla
//   accepts wrong-place loop closures between far places (true positions more than 12 m apart)
//   and the Wi-Fi variant none, with a lower trajectory error (RGBD-SLAM: and fewer long-term
//   comparisons). Deterministic counters only, fixed seed.
// - On the twin-corridor scene of `wifislam demo` (two look-alike corridors 30 m apart, the second
//   walked in both directions), two seeds: vanilla accepts wrong-place closures between the
//   corridors, the Wi-Fi variant none, and its trajectory error is lower in each seed; and the
//   comparison's files, paired runs and Wi-Fi clusters that tell the corridors apart.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <unistd.h>

#include "apps/demo_scene.hpp"
#include "core/error.hpp"
#include "sim/scene/scene_loader.hpp"
#include "study/comparison_study.hpp"
#include "tests/support/read_file.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::study {
namespace {

/// One comparison run (2 seeds x {vanilla, wifi}) checked in one test: ctest runs every test in a
/// process of its own, so splitting the checks would run the whole comparison once per check.
TEST(WifiBoundingClaim, OnTheDemoSceneWifiRemovesTheClosuresBetweenLookAlikeCorridors) {
  const std::filesystem::path out = test::scratch_folder();
  ComparisonOptions options("rgbdslam", {"min_matches=10"});
  options.seeds = 2;
  options.jobs = 2;
  options.plots = false;
  // The claim is in the runs and their evaluation (depth only): no colour PNGs to encode.
  options.dataset_colour = false;
  sim::scene::Scene scene = sim::scene::load_scene_yaml(cli::kDemoSceneYaml, "<demo scene>");
  scene.seed = 7;  // seeds 7 and 8 (the demo's)
  const ComparisonResult result = run_comparison({scene}, options, out);

  ASSERT_EQ(result.cases.size(), 4u);  // 2 seeds x {vanilla, wifi}
  std::int64_t vanilla_far = 0;
  std::map<std::uint64_t, double> vanilla_ate, wifi_ate;
  for (const ComparisonCase& c : result.cases) {
    const eval::RunEvaluation& e = c.evaluation;
    SCOPED_TRACE(c.run_dir.string());
    EXPECT_GT(e.frames_associated, 700);
    const std::int64_t far = e.loop_closure_score.online.far_wrong_place;
    if (c.wifi) {
      EXPECT_GT(e.wifi_clusters, 2);  // the two corridors and the hall are told apart
      EXPECT_EQ(far, 0) << "Wi-Fi closed a loop between the corridors";
      wifi_ate[c.seed] = e.ate_rmse_m;
    } else {
      EXPECT_EQ(e.wifi_clusters, 0);
      vanilla_far += far;
      vanilla_ate[c.seed] = e.ate_rmse_m;
    }
  }
  EXPECT_GE(vanilla_far, 1) << "vanilla RGBD-SLAM should fall for the look-alike corridors";
  ASSERT_EQ(wifi_ate.size(), 2u);
  for (const auto& [seed, ate] : wifi_ate) EXPECT_LT(ate, vanilla_ate.at(seed)) << "seed " << seed;

  // The comparison's files: tables, one CSV row per run, every run folder with its evaluation.
  const std::string md = test::read_file(out / "comparison.md");
  EXPECT_NE(md.find("| scene | min_matches=10 Vanilla | min_matches=10 WiFi |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("| twin_corridors |"), std::string::npos);
  EXPECT_NE(md.find("False positive loop closures"), std::string::npos);
  // Paired runs: each Wi-Fi run is compared with its vanilla twin, and they part ways somewhere
  // after the first keyframe (before the first scan both runs draw the same).
  ASSERT_EQ(result.divergences.size(), 2u);
  for (const PairDivergence& d : result.divergences) EXPECT_GT(d.keyframe, 0) << d.seed;
  EXPECT_NE(md.find("First keyframe where the WiFi run differs"), std::string::npos);
  const std::string csv = test::read_file(out / "comparison.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);  // header + 4 runs
  for (const ComparisonCase& c : result.cases) {
    EXPECT_TRUE(std::filesystem::exists(out / c.run_dir / "trajectory.txt"));
    EXPECT_TRUE(std::filesystem::exists(out / c.run_dir / "eval" / "metrics.json"));
    EXPECT_EQ(std::filesystem::exists(out / c.run_dir / "wifi_clusters.csv"), c.wifi);
  }
  std::filesystem::remove_all(out);
}

/// One dataset, two front ends: RGBD-SLAM (the paper's "RGBD SLAM performance") and the ORB-SLAM
/// style front end ("ORB-SLAM performance"), each vanilla and with Wi-Fi, at default settings.
TEST(WifiBoundingClaim, OnTheCHallTwinWifiCutsFarFalseLoopClosuresComparisonsAndError) {
  const std::filesystem::path out = test::scratch_folder();
  ComparisonOptions options;
  options.seeds = 1;
  options.fps = 3.0;
  // All four runs on one rendering of the dataset (results do not depend on jobs: StreamedRuns).
  options.jobs = 4;
  options.plots = false;
  // The claim is in the runs and their evaluation (depth only): no colour PNGs to encode.
  options.dataset_colour = false;
  options.sweeps = {parse_sweep("frontend=rgbdslam,orbslam")};
  sim::scene::Scene scene =
      sim::scene::load_scene_file(std::string(WIFISLAM_SCENES_DIR) + "/c_hall.yaml");
  scene.seed = 1001;
  const ComparisonResult result = run_comparison({scene}, options, out);
  ASSERT_EQ(result.cases.size(), 4u);
  std::map<std::string, const eval::RunEvaluation*> vanilla, wifi;
  for (const ComparisonCase& c : result.cases) {
    const std::string frontend =
        c.setting.find("orbslam") != std::string::npos ? "orbslam" : "rgbdslam";
    (c.wifi ? wifi : vanilla)[frontend] = &c.evaluation;
  }
  ASSERT_EQ(vanilla.size(), 2u);
  ASSERT_EQ(wifi.size(), 2u);
  const auto long_term = [](const eval::RunEvaluation& e) {
    const auto it = e.timing.roles.find("long_term");
    return it == e.timing.roles.end() ? std::int64_t{0} : it->second.comparisons;
  };
  for (const std::string frontend : {"rgbdslam", "orbslam"}) {
    SCOPED_TRACE(frontend);
    const eval::RunEvaluation& v = *vanilla.at(frontend);
    const eval::RunEvaluation& w = *wifi.at(frontend);
    // Wrong-place closures between places truly more than 12 m apart (eval's far_distance_m), as
    // accepted online.
    const std::int64_t vanilla_far = v.loop_closure_score.online.far_wrong_place;
    const std::int64_t wifi_far = w.loop_closure_score.online.far_wrong_place;
    std::printf(
        "c_hall seed 1001, 3 fps, %s: far wrong-place closures vanilla %lld, Wi-Fi %lld; "
        "long-term comparisons vanilla %lld, Wi-Fi %lld; ATE vanilla %.2f m, Wi-Fi %.2f m\n",
        frontend.c_str(), static_cast<long long>(vanilla_far), static_cast<long long>(wifi_far),
        static_cast<long long>(long_term(v)), static_cast<long long>(long_term(w)), v.ate_rmse_m,
        w.ate_rmse_m);
    // Measured: rgbdslam vanilla 98, Wi-Fi 0; orbslam (min_matches 20) vanilla 5, Wi-Fi 0.
    EXPECT_GE(vanilla_far, 1) << "vanilla should fall for the look-alike sides";
    // The paper: Wi-Fi "gets rid of all false loop closures".
    EXPECT_EQ(wifi_far, 0);
    EXPECT_LT(w.ate_rmse_m, v.ate_rmse_m);
  }
  // RGBD-SLAM's long-term candidates are what Wi-Fi bounds (ORB-SLAM's are bounded in the index
  // lookup, before any verification: its verified candidates are the few consistent ones).
  // "Fewer", not a ratio: the Wi-Fi budget is vanilla's (4) by design, so the saving is the
  // keyframes whose similar clusters hold fewer than 4 keyframes that qualify as a loop closure,
  // which is what the route gives (measured 0.53-0.55 of vanilla's on this twin at
  // min_matches 20, 50 and 70), not a parameter to tune to a figure.
  EXPECT_LT(long_term(*wifi.at("rgbdslam")), long_term(*vanilla.at("rgbdslam")));
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
