// Bounding loop-closure search in RGBD-SLAM holding the Wi-Fi module: the random earlier
// keyframes come only from similar Wi-Fi clusters; predecessors and neighbours are untouched; no
// Wi-Fi information falls back to vanilla sampling.

#include <gtest/gtest.h>

#include <set>

#include "core/error.hpp"
#include "slam/frontend/rgbdslam/rgbdslam_front_end.hpp"
#include "tests/slam/wifi/synthetic_scans.hpp"

namespace wifislam::slam {
namespace {

using test::kPlaceA;
using test::kPlaceB;
using test::scan_of;

/// Drives RGBD-SLAM holding a Wi-Fi module over a chain of keyframes, each tracked from the
/// previous one.
class Driver {
 public:
  explicit Driver(frontend::rgbdslam::RgbdslamOptions rgbdslam = {}, wifi::WifiOptions wifi = {})
      : rule_(/*min_keyframe_gap=*/15, /*min_path_m=*/0.0) {
    wifi.enabled = true;
    selector_ = std::make_unique<frontend::rgbdslam::RgbdslamFrontEnd>(rgbdslam, /*seed=*/5);
    selector_->attach_wifi(std::make_unique<wifi::WifiModule>(wifi, instrumentation_));
  }
  std::vector<frontend::Candidate> add_keyframe() {
    const graph::KeyframeId id = graph_.add_node(Timestamp::from_ns(graph_.node_count()),
                                                 graph_.node_count(), Pose::Identity());
    if (id > 0) graph_.add_edge({id - 1, id, graph::EdgeType::kVisual});
    rule_.add_keyframe(static_cast<double>(id));
    frontend::SelectionQuery q;
    q.keyframe = id;
    q.graph = &graph_;
    q.loop_rule = &rule_;
    if (id > 0) q.already_compared = {id - 1};
    std::vector<frontend::Candidate> c = selector_->candidates_for(q);
    frontend::VerificationReport report;
    report.keyframe = id;
    report.tracked_from = id - 1;
    selector_->on_verified(report);
    return c;
  }
  frontend::rgbdslam::RgbdslamFrontEnd& selector() { return *selector_; }
  const wifi::WifiClusterMap& clusters() const { return selector_->wifi()->clusters(); }
  util::Instrumentation& instrumentation() { return instrumentation_; }

 private:
  util::Instrumentation instrumentation_;
  graph::PoseGraph graph_;
  frontend::LoopRule rule_;
  std::unique_ptr<frontend::rgbdslam::RgbdslamFrontEnd> selector_;
};

std::set<graph::KeyframeId> sampled(const std::vector<frontend::Candidate>& candidates) {
  std::set<graph::KeyframeId> out;
  for (const frontend::Candidate& c : candidates) {
    if (c.role == frontend::CandidateRole::kLongTerm) out.insert(c.keyframe);
  }
  return out;
}

TEST(WifiRgbdslamSelection, LongTermCandidatesComeOnlyFromSimilarClusters) {
  Driver d;
  d.selector().observe_wifi_scan(scan_of(0, kPlaceA));
  for (int i = 0; i < 30; ++i) d.add_keyframe();  // 0..29 at A
  d.selector().observe_wifi_scan(scan_of(100, kPlaceB));
  for (int i = 0; i < 30; ++i) d.add_keyframe();  // 30..59 at B
  ASSERT_EQ(d.clusters().clusters().size(), 2u);
  d.selector().observe_wifi_scan(scan_of(200, kPlaceA));
  for (int i = 0; i < 10; ++i) {  // back at A: 60..69
    const std::set<graph::KeyframeId> s = sampled(d.add_keyframe());
    EXPECT_EQ(s.size(), 4u);
    for (graph::KeyframeId k : s) EXPECT_LT(k, 30) << "keyframe " << k << " is at B";
  }
  // At B the pool is B's keyframes old enough to close a loop (30..(query-15)).
  d.selector().observe_wifi_scan(scan_of(300, kPlaceB));
  const std::set<graph::KeyframeId> s = sampled(d.add_keyframe());  // keyframe 70
  ASSERT_EQ(s.size(), 4u);
  for (graph::KeyframeId k : s) {
    EXPECT_GE(k, 30);
    EXPECT_LE(k, 55);
  }
  EXPECT_GT(d.instrumentation().counter(counter::kWifiSimilarityComparisons), 0);
}

TEST(WifiRgbdslamSelection, PredecessorsStayAndRecentKeyframesAreNotLongTermCandidates) {
  Driver d;
  d.selector().observe_wifi_scan(scan_of(0, kPlaceA));
  std::vector<frontend::Candidate> c;
  for (int i = 0; i < 12; ++i) c = d.add_keyframe();
  // Keyframe 11: predecessor 10 was compared by tracking, 9, 8, 7 are returned; the cluster's
  // other keyframes are all within the loop gap, so nothing long-term.
  ASSERT_FALSE(c.empty());
  EXPECT_EQ(c[0].keyframe, 9);
  EXPECT_EQ(c[0].role, frontend::CandidateRole::kPredecessor);
  EXPECT_TRUE(sampled(c).empty());
}

TEST(WifiRgbdslamSelection, ZeroSampledCandidatesMeansEveryKeyframeOfTheSimilarClusters) {
  frontend::rgbdslam::RgbdslamOptions rgbdslam;
  rgbdslam.wifi_long_term_candidates = 0;
  Driver d(rgbdslam);
  d.selector().observe_wifi_scan(scan_of(0, kPlaceA));
  for (int i = 0; i < 20; ++i) d.add_keyframe();
  d.selector().observe_wifi_scan(scan_of(100, kPlaceB));
  for (int i = 0; i < 20; ++i) d.add_keyframe();
  d.selector().observe_wifi_scan(scan_of(200, kPlaceA));
  const std::set<graph::KeyframeId> s = sampled(d.add_keyframe());  // keyframe 40
  std::set<graph::KeyframeId> expected;
  for (graph::KeyframeId k = 0; k < 20; ++k) expected.insert(k);
  // Neighbour sampling may have taken a couple of them already; the rest must all be here.
  for (graph::KeyframeId k : s) EXPECT_TRUE(expected.count(k));
  EXPECT_GE(s.size(), 18u);
}

TEST(WifiRgbdslamSelection, TheMostSimilarSignaturesComeFirst) {
  // A and A2 are similar (cosine >= 0.9) but not identical; back at A, the 4 long-term
  // candidates all come from A's own pause, never from A2's, though both clusters are similar.
  const std::vector<std::pair<std::uint64_t, int>> place_a2 = {
      {0x10, -45}, {0x20, -60}, {0x30, -85}};
  Driver d;
  d.selector().observe_wifi_scan(scan_of(0, kPlaceA));
  for (int i = 0; i < 20; ++i) d.add_keyframe();  // 0..19
  d.selector().observe_wifi_scan(scan_of(100, kPlaceB));
  for (int i = 0; i < 20; ++i) d.add_keyframe();  // 20..39
  d.selector().observe_wifi_scan(scan_of(200, place_a2));
  for (int i = 0; i < 20; ++i) d.add_keyframe();  // 40..59, a cluster of their own
  d.selector().observe_wifi_scan(scan_of(300, kPlaceA));
  const std::set<graph::KeyframeId> s = sampled(d.add_keyframe());  // 60
  ASSERT_EQ(s.size(), 4u);
  for (graph::KeyframeId k : s) EXPECT_LT(k, 20) << k;
}

TEST(WifiRgbdslamSelection, NoQualifyingKeyframeInASimilarClusterMeansNoLongTermCandidate) {
  Driver d;
  d.selector().observe_wifi_scan(scan_of(0, kPlaceA));
  for (int i = 0; i < 30; ++i) d.add_keyframe();
  d.selector().observe_wifi_scan(scan_of(100, kPlaceB));
  // New place: no similar cluster yet, so no long-term comparison at all (vanilla would draw 4).
  EXPECT_TRUE(sampled(d.add_keyframe()).empty());
}

TEST(WifiRgbdslamSelection, VanillaAndWifiDrawTheSameWhereWifiDoesNotAct) {
  // Same seed, same keyframes: before the first scan the Wi-Fi run samples its long-term
  // candidates exactly as vanilla does, and its neighbours always match vanilla's.
  Driver wifi;
  frontend::rgbdslam::RgbdslamFrontEnd vanilla(frontend::rgbdslam::RgbdslamOptions{}, /*seed=*/5);
  graph::PoseGraph graph;
  frontend::LoopRule rule(15, 0.0);
  for (graph::KeyframeId id = 0; id < 60; ++id) {
    if (id == 40) wifi.selector().observe_wifi_scan(scan_of(0, kPlaceA));
    const std::vector<frontend::Candidate> w = wifi.add_keyframe();
    graph.add_node(Timestamp::from_ns(id), id, Pose::Identity());
    if (id > 0) graph.add_edge({id - 1, id, graph::EdgeType::kVisual});
    rule.add_keyframe(static_cast<double>(id));
    frontend::SelectionQuery q;
    q.keyframe = id;
    q.graph = &graph;
    q.loop_rule = &rule;
    if (id > 0) q.already_compared = {id - 1};
    const std::vector<frontend::Candidate> v = vanilla.candidates_for(q);
    if (id < 40) {
      EXPECT_EQ(w, v) << "keyframe " << id;
    } else {
      std::vector<frontend::Candidate> wn, vn;
      for (const frontend::Candidate& c : w)
        if (c.role != frontend::CandidateRole::kLongTerm) wn.push_back(c);
      for (const frontend::Candidate& c : v)
        if (c.role != frontend::CandidateRole::kLongTerm) vn.push_back(c);
      EXPECT_EQ(wn, vn) << "keyframe " << id;
    }
  }
}

TEST(WifiRgbdslamSelection, WithoutWifiInformationItSamplesLikeVanilla) {
  Driver d;
  for (int i = 0; i < 40; ++i) d.add_keyframe();
  EXPECT_EQ(d.instrumentation().counter(counter::kWifiUnsignedKeyframes), 40);
  EXPECT_TRUE(d.clusters().clusters().empty());
}

}  // namespace
}  // namespace wifislam::slam
