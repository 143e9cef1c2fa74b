// SLAM options: `--set key=value` parsing, validation and run.json form.

#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "slam/slam_options.hpp"

namespace wifislam::slam {
namespace {

TEST(SlamOptions, DefaultsAreRgbdslamV2s) {
  const SlamOptions o;
  EXPECT_EQ(o.features.max_keypoints, 600);
  EXPECT_EQ(o.transform.min_matches, 20);
  EXPECT_EQ(o.transform.ransac_iterations, 200);
  EXPECT_EQ(o.rgbdslam.predecessor_candidates, 4);
  EXPECT_EQ(o.rgbdslam.neighbor_candidates, 4);
  EXPECT_EQ(o.rgbdslam.geodesic_depth, 3);
  EXPECT_EQ(o.rgbdslam.min_sampled_candidates, 4);
  EXPECT_EQ(o.rgbdslam.wifi_long_term_candidates, -1);
  EXPECT_NO_THROW(validate(o));
}

// Issue 34: `--frontend orbslam --set frontend=rtabmap` ran RTAB-Map without a word. The
// assignment may repeat --frontend's choice, never contradict it.
TEST(SlamOptions, SetFrontendConflictingWithFrontendIsRefused) {
  SlamOptions o;
  o.frontend = "orbslam";
  try {
    set_option_assignment(o, "frontend=rtabmap");
    ADD_FAILURE() << "the conflict was accepted";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("conflicts with --frontend orbslam"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(o.frontend, "orbslam");
  EXPECT_NO_THROW(set_option_assignment(o, "frontend=orbslam"));
  EXPECT_EQ(o.frontend, "orbslam");
}

// A floor above 0 dBm weighted no AP and one far below every receiver weighted all alike: either
// turned Wi-Fi clustering off without a word.
TEST(SlamOptions, WifiFloorOutsideReceivedPowersIsRefused) {
  for (const char* bad : {"wifi_floor_dbm=50", "wifi_floor_dbm=-1e300", "wifi_floor_dbm=0.5"}) {
    SlamOptions o;
    set_option_assignment(o, bad);
    EXPECT_THROW(validate(o), InvalidInputError) << bad;
  }
  SlamOptions o;
  set_option_assignment(o, "wifi_floor_dbm=-110");
  EXPECT_NO_THROW(validate(o));
}

/// `assignment` ("key=value") is refused where it is set (a choice) or by validate(), and the
/// error names its key.
void expect_refused_naming_its_key(const std::string& assignment) {
  SlamOptions o;
  const std::string key = assignment.substr(0, assignment.find('='));
  try {
    set_option_assignment(o, assignment);
    validate(o);
    ADD_FAILURE() << assignment << " was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
  }
}

// Values that passed validation and then gave a run that could find nothing (no FAST corner in
// an 8-bit image, no descriptor match) or failed inside it (no short-term memory: RTAB-Map's
// newest node became a loop-closure candidate of itself, an internal error after the work).
TEST(SlamOptions, ValuesARunCannotUseAreRefusedNamingTheKey) {
  for (const char* bad : {"fast_threshold=256", "fast_threshold=-1", "max_hamming_distance=-1",
                          "max_hamming_distance=257", "optimizer_convergence=-1",
                          "optimizer_convergence=inf", "stm_size=0"}) {
    expect_refused_naming_its_key(bad);
  }
  for (const char* edge : {"fast_threshold=0", "fast_threshold=255", "max_hamming_distance=0",
                           "max_hamming_distance=256", "optimizer_convergence=0", "stm_size=1"}) {
    SlamOptions o;
    set_option_assignment(o, edge);
    EXPECT_NO_THROW(validate(o)) << edge;
  }
}

// `--set vocabulary=...` with the rgbdslam front end changed nothing without a word.
TEST(SlamOptions, AnOptionOfAnotherFrontEndIsNamedAsUnread) {
  EXPECT_EQ(option_front_end("vocabulary"), "orbslam");
  EXPECT_EQ(option_front_end("stm_size"), "rtabmap");
  EXPECT_EQ(option_front_end("predecessor_candidates"), "rgbdslam");
  EXPECT_EQ(option_front_end("wifi_max_retrieved"), "rtabmap") << "rtabmap with Wi-Fi: ...";
  EXPECT_EQ(option_front_end("min_matches"), "") << "every front end reads it";
  EXPECT_EQ(option_front_end("no_such_key"), "");
  const std::vector<std::string> one =
      unread_option_warnings({"vocabulary", "min_matches", "stm_size"}, {"rgbdslam"});
  ASSERT_EQ(one.size(), 2u);
  EXPECT_NE(one[0].find("vocabulary is an option of the orbslam front end; rgbdslam does not"),
            std::string::npos)
      << one[0];
  EXPECT_NE(one[1].find("stm_size"), std::string::npos) << one[1];
  // A sweep over front ends: read by one of them is read.
  EXPECT_TRUE(unread_option_warnings({"vocabulary"}, {"rgbdslam", "orbslam"}).empty());
  const std::vector<std::string> two =
      unread_option_warnings({"stm_size"}, {"rgbdslam", "orbslam"});
  ASSERT_EQ(two.size(), 1u);
  EXPECT_NE(two[0].find("none of rgbdslam, orbslam reads it"), std::string::npos) << two[0];
  EXPECT_TRUE(unread_option_warnings({"stm_size"}, {"external:x.yaml"}).empty());
}

TEST(SlamOptions, RefusesABadKernelOrPruningScheduleNamingIt) {
  for (const char* bad : {"robust_kernel=tukey", "prune_chi2=5,,1", "prune_chi2=5,-1",
                          "prune_chi2=abc", "prune_chi2=nan", "robust_kernel_chi2=0"}) {
    expect_refused_naming_its_key(bad);
  }
  SlamOptions none;
  set_option_assignment(none, "prune_chi2=none");
  EXPECT_NO_THROW(validate(none));
}

TEST(SlamOptions, SetsThePapersParametersByName) {
  SlamOptions o;
  set_option_assignment(o, "min_matches=15");
  set_option_assignment(o, "inlier_distance=2.5");
  set_option_assignment(o, "odometry_edges=true");
  set_option_assignment(o, "robust_kernel=cauchy");
  set_option_assignment(o, "prune_chi2=30, 10");
  set_option_assignment(o, "seed=42");
  EXPECT_EQ(o.transform.min_matches, 15);
  EXPECT_DOUBLE_EQ(o.transform.inlier_distance, 2.5);
  EXPECT_TRUE(o.tracking.odometry_edges);
  EXPECT_EQ(o.rgbdslam.robust_kernel, optimize::RobustKernel::Kind::kCauchy);
  EXPECT_NO_THROW(validate(o));
  EXPECT_EQ(o.seed, 42u);
  const nlohmann::json j = to_json(o);
  EXPECT_EQ(j.at("min_matches"), 15);
  EXPECT_EQ(j.at("inlier_distance"), 2.5);
}

TEST(SlamOptions, BadInputNamesTheKey) {
  SlamOptions o;
  try {
    set_option_assignment(o, "min_match=15");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.key_path(), "min_match");
    EXPECT_NE(std::string(e.what()).find("did you mean 'min_matches'?"), std::string::npos)
        << e.what();
  }
  // The rules every option table shares (core/option_table.hpp): whole numbers for integers.
  EXPECT_THROW(set_option_assignment(o, "min_matches=15.0"), ParseError);
  EXPECT_THROW(set_option_assignment(o, "min_matches=lots"), ParseError);
  EXPECT_THROW(set_option_assignment(o, "min_matches"), ParseError);
  EXPECT_THROW(set_option_assignment(o, "odometry_edges=maybe"), ParseError);
  set_option_assignment(o, "ransac_confidence=1.0");
  EXPECT_THROW(validate(o), InvalidInputError);  // OpenCV asserts at exactly 1
}

TEST(SlamOptions, RtabmapParametersHaveRtabmapDefaultsAndTimeThresholdTakesInf) {
  SlamOptions o;
  EXPECT_EQ(o.rtabmap.stm_size, 10);                     // Mem/STMSize
  EXPECT_EQ(o.rtabmap.rehearsal_similarity, 0.6);        // Mem/RehearsalSimilarity
  EXPECT_EQ(o.rtabmap.max_features, 500);                // Kp/MaxFeatures
  EXPECT_EQ(o.rtabmap.nndr_ratio, 0.8);                  // Kp/NndrRatio
  EXPECT_EQ(o.rtabmap.virtual_place_prior, 0.9);         // Bayes/VirtualPlacePriorThr
  EXPECT_EQ(o.rtabmap.loop_threshold, 0.11);             // Rtabmap/LoopThr
  EXPECT_EQ(o.rtabmap.max_retrieved, 2);                 // Rtabmap/MaxRetrieved
  EXPECT_EQ(o.rtabmap.optimize_max_error, 3.0);          // RGBD/OptimizeMaxError
  EXPECT_TRUE(std::isinf(o.rtabmap.time_threshold_ms));  // Rtabmap/TimeThr off
  EXPECT_EQ(to_json(o).at("time_threshold_ms"), "inf");
  set_option_assignment(o, "time_threshold_ms=70");
  EXPECT_EQ(o.rtabmap.time_threshold_ms, 70.0);
  set_option_assignment(o, "time_threshold_ms=inf");
  EXPECT_TRUE(std::isinf(o.rtabmap.time_threshold_ms));
  EXPECT_THROW(set_option_assignment(o, "kp_nndr_ratio=inf"), ParseError);  // only the threshold
  set_option_assignment(o, "bayes_prediction_lc=0.1 0.5 0.4");
  EXPECT_NO_THROW(validate(o));
  set_option_assignment(o, "bayes_prediction_lc=0.1");
  EXPECT_THROW(validate(o), InvalidInputError);
  o.rtabmap.prediction_lc = "0.1 0.36";
  // A time source is one of its names, refused where it is set.
  EXPECT_THROW(set_option_assignment(o, "time_source=sundial"), Error);
  set_option_assignment(o, "time_source=wall");
  EXPECT_EQ(o.rtabmap.time_source, frontend::rtabmap::RtabmapTimeSource::kWall);
  EXPECT_NO_THROW(validate(o));
  for (const char* bad :
       {"cost_ms_per_scored_node=-1", "cost_ms_per_hypothesis=-1", "wifi_max_immune=-1"}) {
    SlamOptions b;
    set_option_assignment(b, bad);
    EXPECT_THROW(validate(b), InvalidInputError) << bad;
  }
}

// `wifislam slam --help` lists every --set key with its default, and each listed default reads
// back through set_option to the same options.
TEST(SlamOptions, TheHelpReferenceListsEveryKeyWithADefaultThatReadsBack) {
  const std::string reference = option_reference();
  for (const std::string& key : options::option_keys<SlamOptions>()) {
    const std::string prefix = "  " + key + "=";
    const std::size_t at = reference.find(prefix);
    ASSERT_NE(at, std::string::npos) << key;
    const std::size_t end = reference.find('\n', at);
    SlamOptions read_back;
    set_option(read_back, key, reference.substr(at + prefix.size(), end - at - prefix.size()));
    EXPECT_EQ(to_json(read_back), to_json(SlamOptions{})) << key;
  }
  EXPECT_NE(reference.find("  time_threshold_ms=inf\n"), std::string::npos);
  EXPECT_NE(reference.find("Rtabmap/TimeThr"), std::string::npos);
}

}  // namespace
}  // namespace wifislam::slam
