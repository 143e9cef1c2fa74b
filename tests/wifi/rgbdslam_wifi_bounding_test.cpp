// Bounding loop-closure search in RGBD-SLAM holding the Wi-Fi module: the random earlier
// keyframes come only from similar Wi-Fi clusters; predecessors and neighbours are untouched; no
// Wi-Fi information falls back to vanilla sampling.

#include <gtest/gtest.h>

#include <set>

#include "core/error.hpp"
#include "slam/frontend/rgbdslam/rgbdslam_front_end.hpp"

namespace wifislam::slam {
namespace {

WifiScan scan_of(double start_s, std::vector<std::pair<std::uint64_t, int>> aps) {
  WifiScan scan;
  scan.start_time = Timestamp::from_seconds(start_s);
  scan.end_time = scan.time = Timestamp::from_seconds(start_s + 1.0);
  for (const auto& [ap, rssi] : aps)
    scan.readings.push_back({MacAddress{ap}, 2412000, rssi, "corp"});
  return scan;
}

const std::vector<std::pair<std::uint64_t, int>> kPlaceA = {{0x10, -40}, {0x20, -60}, {0x30, -90}};
const std::vector<std::pair<std::uint64_t, int>> kPlaceB = {{0x10, -90}, {0x20, -60}, {0x30, -40}};

/// Drives RGBD-SLAM holding a Wi-Fi module over a chain of keyframes, each tracked from the
/// previous one.
class Driver {
 public:
  explicit Driver(WifiOptions wifi = {}) : rule_(/*min_keyframe_gap=*/15, /*min_path_m=*/0.0) {
    wifi.enabled = true;
    selector_ = std::make_unique<RgbdslamFrontEnd>(RgbdslamOptions{}, wifi.sampled_candidates,
                                                   /*seed=*/5);
    selector_->attach_wifi(std::make_unique<WifiModule>(wifi, instrumentation_));
  }
  std::vector<Candidate> add_keyframe() {
    const KeyframeId id = graph_.add_node(Timestamp::from_ns(graph_.node_count()),
                                          graph_.node_count(), Pose::Identity());
    if (id > 0) graph_.add_edge({id - 1, id, EdgeType::kVisual});
    rule_.add_keyframe(static_cast<double>(id));
    SelectionQuery q;
    q.keyframe = id;
    q.graph = &graph_;
    q.loop_rule = &rule_;
    if (id > 0) q.already_compared = {id - 1};
    std::vector<Candidate> c = selector_->select(q);
    VerificationReport report;
    report.keyframe = id;
    report.tracked_from = id - 1;
    selector_->on_verified(report);
    return c;
  }
  RgbdslamFrontEnd& selector() { return *selector_; }
  const WifiClusterMap& clusters() const { return selector_->wifi()->clusters(); }
  Instrumentation& instrumentation() { return instrumentation_; }

 private:
  Instrumentation instrumentation_;
  PoseGraph graph_;
  LoopRule rule_;
  std::unique_ptr<RgbdslamFrontEnd> selector_;
};

std::set<KeyframeId> sampled(const std::vector<Candidate>& candidates) {
  std::set<KeyframeId> out;
  for (const Candidate& c : candidates) {
    if (c.role == CandidateRole::kLongTerm) out.insert(c.keyframe);
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
    const std::set<KeyframeId> s = sampled(d.add_keyframe());
    EXPECT_EQ(s.size(), 2u);
    for (KeyframeId k : s) EXPECT_LT(k, 30) << "keyframe " << k << " is at B";
  }
  // At B the pool is B's keyframes old enough to close a loop (30..(query-15)).
  d.selector().observe_wifi_scan(scan_of(300, kPlaceB));
  const std::set<KeyframeId> s = sampled(d.add_keyframe());  // keyframe 70
  ASSERT_EQ(s.size(), 2u);
  for (KeyframeId k : s) {
    EXPECT_GE(k, 30);
    EXPECT_LE(k, 55);
  }
  EXPECT_GT(d.instrumentation().counter(counter::kWifiSimilarityComparisons), 0);
}

TEST(WifiRgbdslamSelection, PredecessorsStayAndRecentKeyframesAreNotLongTermCandidates) {
  Driver d;
  d.selector().observe_wifi_scan(scan_of(0, kPlaceA));
  std::vector<Candidate> c;
  for (int i = 0; i < 12; ++i) c = d.add_keyframe();
  // Keyframe 11: predecessor 10 was compared by tracking, 9 is returned; the cluster's other
  // keyframes are all within the loop gap, so nothing long-term.
  ASSERT_FALSE(c.empty());
  EXPECT_EQ(c[0].keyframe, 9);
  EXPECT_EQ(c[0].role, CandidateRole::kPredecessor);
  EXPECT_TRUE(sampled(c).empty());
}

TEST(WifiRgbdslamSelection, ZeroSampledCandidatesMeansEveryKeyframeOfTheSimilarClusters) {
  WifiOptions wifi;
  wifi.sampled_candidates = 0;
  Driver d(wifi);
  d.selector().observe_wifi_scan(scan_of(0, kPlaceA));
  for (int i = 0; i < 20; ++i) d.add_keyframe();
  d.selector().observe_wifi_scan(scan_of(100, kPlaceB));
  for (int i = 0; i < 20; ++i) d.add_keyframe();
  d.selector().observe_wifi_scan(scan_of(200, kPlaceA));
  const std::set<KeyframeId> s = sampled(d.add_keyframe());  // keyframe 40
  std::set<KeyframeId> expected;
  for (KeyframeId k = 0; k < 20; ++k) expected.insert(k);
  // Neighbour sampling may have taken a couple of them already; the rest must all be here.
  for (KeyframeId k : s) EXPECT_TRUE(expected.count(k));
  EXPECT_GE(s.size(), 18u);
}

TEST(WifiRgbdslamSelection, WithoutWifiInformationItSamplesLikeVanilla) {
  Driver d;
  for (int i = 0; i < 40; ++i) d.add_keyframe();
  EXPECT_EQ(d.instrumentation().counter(counter::kWifiUnsignedKeyframes), 40);
  EXPECT_TRUE(d.clusters().clusters().empty());
}

}  // namespace
}  // namespace wifislam::slam
