// Requirements on an evaluation (eval/requirement.hpp): "<=" is not read as "<" then "=...",
// spaces are allowed, malformed text and unknown metrics are refused with the metric's nearest
// name, a metric the run lacks (or did not measure) is not met, and the message says by how much a
// bound is missed.
#include "eval/requirement.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "eval/run_evaluation.hpp"

namespace wifislam::eval {
namespace {

TEST(Requirement, ParsesEveryOperatorWithOrWithoutSpaces) {
  const Requirement a = parse_requirement("ate_rmse_m<=0.5");
  EXPECT_EQ(a.metric, "ate_rmse_m");
  EXPECT_EQ(a.comparison, Comparison::kLessEqual);
  EXPECT_EQ(a.bound, 0.5);
  EXPECT_EQ(parse_requirement(" ate_rmse_m < 2 ").comparison, Comparison::kLess);
  EXPECT_EQ(parse_requirement("online_wrong_place == 0").comparison, Comparison::kEqual);
  EXPECT_EQ(parse_requirement("frames_associated>=10").comparison, Comparison::kGreaterEqual);
  EXPECT_EQ(parse_requirement("frames_associated>10").comparison, Comparison::kGreater);
  EXPECT_EQ(parse_requirement("online_wrong_place!=3").comparison, Comparison::kNotEqual);
  EXPECT_EQ(parse_requirement("x<=-1e-3").bound, -1e-3);
}

TEST(Requirement, MalformedTextIsBadInput) {
  for (const char* text : {"ate_rmse_m", "<=0.5", "ate_rmse_m<=", "ate_rmse_m<=abc",
                           "ate_rmse_m<=nan", "ate_rmse_m<=inf", "a<b<=1", "ate_rmse_m=0.5"}) {
    EXPECT_THROW(parse_requirement(text), InvalidInputError) << text;
  }
}

TEST(Requirement, UnknownMetricsAreRefusedWithTheNearestName) {
  const nlohmann::ordered_json flat = {{"ate_rmse_m", 0.3}, {"frontend", "rgbdslam"}};
  try {
    check_metric_names({parse_requirement("ate_rms_m<=1")}, flat);
    FAIL() << "accepted an unknown metric";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'ate_rmse_m'"), std::string::npos)
        << e.what();
  }
  // A text column is named as one, not suggested as its own nearest name.
  try {
    check_metric_names({parse_requirement("frontend==1")}, flat);
    FAIL() << "accepted a text column";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("'frontend' holds text ('rgbdslam'), not a number"),
              std::string::npos)
        << e.what();
    EXPECT_EQ(std::string(e.what()).find("did you mean"), std::string::npos) << e.what();
  }
  // A column a run folder's row has, absent from this (trajectory file's) row: known, not met.
  const auto results = check_requirements({parse_requirement("online_wrong_place==0")}, flat);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_FALSE(results[0].met);
  EXPECT_FALSE(results[0].value.has_value());
  EXPECT_NE(results[0].describe().find("not available"), std::string::npos);
}

TEST(Requirement, ResultsSayWhetherAndByHowMuch) {
  const nlohmann::ordered_json flat = {{"ate_rmse_m", 0.75}, {"online_wrong_place", 0}};
  const auto results = check_requirements(
      {parse_requirement("ate_rmse_m<=0.5"), parse_requirement("ate_rmse_m<1"),
       parse_requirement("online_wrong_place==0"), parse_requirement("ate_rmse_m<0.75")},
      flat);
  ASSERT_EQ(results.size(), 4u);
  EXPECT_FALSE(results[0].met);
  EXPECT_EQ(results[0].describe(),
            "NOT met: ate_rmse_m = 0.75 (ate_rmse_m <= 0.5 fails), above 0.5 by 0.25");
  EXPECT_TRUE(results[1].met);
  EXPECT_EQ(results[1].describe(), "met: ate_rmse_m = 0.75 < 1");
  EXPECT_TRUE(results[2].met);
  EXPECT_FALSE(results[3].met);  // a strict bound equal to the value
  EXPECT_NE(results[3].describe().find("equal to 0.75"), std::string::npos);
}

// A route shorter than rpe_delta_m measures no RPE pair: its RPE was written as 0, and
// `--require rpe_trans_per_m<=0.001` passed on a run nothing was measured of. It is null now, and
// a requirement on it is not met; with pairs the figure is there.
TEST(Requirement, AnRpeWithNoPairIsNullAndNotMet) {
  RunEvaluation unmeasured;
  unmeasured.rpe_pairs = 0;
  const nlohmann::ordered_json flat = unmeasured.flat_metrics();
  for (const char* key :
       {"rpe_trans_per_m", "rpe_rot_deg_per_m", "rpe_trans_rmse_m", "rpe_rot_rmse_deg"}) {
    ASSERT_TRUE(flat.contains(key)) << key;
    EXPECT_TRUE(flat[key].is_null()) << key;
  }
  EXPECT_TRUE(unmeasured.to_ordered_json()["trajectory"]["rpe_trans_per_m"].is_null());
  const auto results = check_requirements({parse_requirement("rpe_trans_per_m<=0.001")}, flat);
  EXPECT_FALSE(results[0].met);
  EXPECT_NE(results[0].describe().find("not available"), std::string::npos);

  RunEvaluation measured;
  measured.rpe_pairs = 12;
  measured.rpe_trans_per_m = 0.0005;
  EXPECT_TRUE(
      check_requirements({parse_requirement("rpe_trans_per_m<=0.001")}, measured.flat_metrics())[0]
          .met);
}

}  // namespace
}  // namespace wifislam::eval
