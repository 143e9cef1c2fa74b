// The paper's claims over a whole part ("no false positives in either approach", "less than 20
// in both", "no false negatives except at min-match=100") against hand-made run rows: per seed,
// the largest value of any run the claim covers decides, so one run against it is enough.
#include <gtest/gtest.h>

#include <algorithm>

#include "study/paper/paper_comparison.hpp"

namespace wifislam::study::paper {
namespace {

RunRow run_row(Part part, const std::string& twin, std::uint64_t seed, const std::string& setting,
               bool wifi, std::map<std::string, double> values) {
  RunRow r;
  r.part = part;
  r.twin = twin;
  r.seed = seed;
  r.setting = setting;
  r.wifi = wifi;
  r.values = std::move(values);
  return r;
}

/// The judged number of the paper with these words' start, part, variant and quantity.
const ComparedNumber& judged(const std::vector<ComparedNumber>& all, Part part,
                             const std::string& words_start, const std::string& setting,
                             Variant variant, Quantity quantity) {
  const auto it = std::find_if(all.begin(), all.end(), [&](const ComparedNumber& c) {
    return c.paper->part == part && c.paper->words.rfind(words_start, 0) == 0 &&
           c.paper->setting == setting && c.paper->variant == variant &&
           c.paper->quantity == quantity;
  });
  if (it == all.end()) throw std::logic_error("no such number: " + words_start);
  return *it;
}

TEST(PaperComparison, OneRtabmapRunWithAWrongPlaceClosureMissesThePapersNone) {
  std::vector<RunRow> rows;
  // Two seeds of A and B Hall at two thresholds; every run without a wrong-place closure but
  // seed 1002's vanilla run on B Hall at 70 ms (25 %).
  for (const char* twin : {"a_hall", "b_hall"}) {
    const std::uint64_t own = std::string(twin) == "a_hall" ? 4004 : 2002;
    for (std::uint64_t seed : {own, own + 1}) {
      for (const char* setting : {"time_threshold_ms=inf", "time_threshold_ms=70"}) {
        for (bool wifi : {false, true}) {
          const bool the_one = std::string(twin) == "b_hall" && seed == own + 1 &&
                               std::string(setting) == "time_threshold_ms=70" && !wifi;
          rows.push_back(run_row(Part::kRtabmap, twin, seed, setting, wifi,
                                 {{"false_positive_pct", the_one ? 25.0 : 0.0},
                                  {"false_negative_pct", 0.0},
                                  {"revisit_episodes", 1.0}}));
        }
      }
    }
  }
  const auto all = compare_with_paper(PaperMeasurements::from_rows(rows));
  const auto& vanilla = judged(all, Part::kRtabmap, "Since there are no false positive", "",
                               Variant::kVanilla, Quantity::kFalsePositivePct);
  EXPECT_EQ(vanilla.ours.per_seed, (std::vector<double>{0.0, 25.0}));
  // One seed with 25 % against the paper's none: missed, whatever the other seed.
  EXPECT_EQ(vanilla.judgement.verdict, Verdict::kDeparts) << vanilla.judgement.why;
  EXPECT_NE(vanilla.judgement.why.find("the worst seed 25"), std::string::npos)
      << vanilla.judgement.why;
  const auto& wifi = judged(all, Part::kRtabmap, "Since there are no false positive", "",
                            Variant::kWifi, Quantity::kFalsePositivePct);
  EXPECT_EQ(wifi.ours.per_seed, (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(wifi.judgement.verdict, Verdict::kReproduced) << wifi.judgement.why;
}

TEST(PaperComparison, FalseNegativesCountOnlyRunsWhoseRouteRevisitsAPlace) {
  std::vector<RunRow> rows;
  // At no threshold: C Hall misses 10 %, J Hall 30 % on a route with no revisit episode (so no
  // false negative % of its own) and 15 % on one with.
  rows.push_back(run_row(Part::kRtabmap, "c_hall", 1001, "time_threshold_ms=inf", false,
                         {{"false_negative_pct", 10.0}, {"revisit_episodes", 2.0}}));
  rows.push_back(run_row(Part::kRtabmap, "j_hall", 3003, "time_threshold_ms=inf", false,
                         {{"false_negative_pct", 30.0}, {"revisit_episodes", 0.0}}));
  rows.push_back(run_row(Part::kRtabmap, "j_hall", 3003, "time_threshold_ms=200", false,
                         {{"false_negative_pct", 35.0}, {"revisit_episodes", 1.0}}));
  const auto all = compare_with_paper(PaperMeasurements::from_rows(rows));
  const auto& inf = judged(all, Part::kRtabmap, "For real-time threshold=200",
                           "time_threshold_ms=inf", Variant::kVanilla, Quantity::kFalseNegativePct);
  EXPECT_EQ(inf.ours.per_seed, (std::vector<double>{10.0}));
  EXPECT_EQ(inf.judgement.verdict, Verdict::kReproduced) << inf.judgement.why;  // below 20
  const auto& at200 =
      judged(all, Part::kRtabmap, "For real-time threshold=200", "time_threshold_ms=200",
             Variant::kVanilla, Quantity::kFalseNegativePct);
  EXPECT_EQ(at200.judgement.verdict, Verdict::kDeparts) << at200.judgement.why;  // 35: not below
  // A second seed of C Hall misses 25 % at no threshold: the mean (17.5) is below 20, the worst
  // seed is not.
  rows.push_back(run_row(Part::kRtabmap, "c_hall", 1002, "time_threshold_ms=inf", false,
                         {{"false_negative_pct", 25.0}, {"revisit_episodes", 1.0}}));
  const auto again = compare_with_paper(PaperMeasurements::from_rows(rows));
  const auto& two_seeds =
      judged(again, Part::kRtabmap, "For real-time threshold=200", "time_threshold_ms=inf",
             Variant::kVanilla, Quantity::kFalseNegativePct);
  EXPECT_EQ(two_seeds.ours.per_seed, (std::vector<double>{10.0, 25.0}));
  EXPECT_EQ(two_seeds.judgement.verdict, Verdict::kDeparts) << two_seeds.judgement.why;

  // ORB-SLAM: min-matches 100 is the paper's exception, so its misses do not count.
  rows.clear();
  rows.push_back(run_row(Part::kOrbslam, "b_hall", 2002, "min_matches=100", true,
                         {{"false_negative_pct", 50.0}, {"revisit_episodes", 1.0}}));
  rows.push_back(run_row(Part::kOrbslam, "b_hall", 2002, "min_matches=10", true,
                         {{"false_negative_pct", 0.0}, {"revisit_episodes", 1.0}}));
  const auto orb = compare_with_paper(PaperMeasurements::from_rows(rows));
  const auto& none = judged(orb, Part::kOrbslam, "Also, there are no false negatives", "",
                            Variant::kWifi, Quantity::kFalseNegativePct);
  EXPECT_EQ(none.ours.per_seed, (std::vector<double>{0.0}));
  EXPECT_EQ(none.judgement.verdict, Verdict::kReproduced) << none.judgement.why;
}

}  // namespace
}  // namespace wifislam::study::paper
