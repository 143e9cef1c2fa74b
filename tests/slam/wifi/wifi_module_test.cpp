// The Wi-Fi module is generic (paper, "General approach"): one class, held by any front end,
// driven only through its public calls. The same scans and the same visual connections give the
// same clusters whether RGBD-SLAM or another front end holds it; bounding, immunisation and
// retrieval answer from the similar clusters of the signed keyframe; listeners hear every
// cluster founded and every join.

#include <gtest/gtest.h>

#include <set>

#include "core/error.hpp"
#include "slam/frontend/front_end_registry.hpp"
#include "slam/frontend/rgbdslam/rgbdslam_front_end.hpp"
#include "slam/wifi/wifi_module.hpp"
#include "tests/slam/wifi/synthetic_scans.hpp"

namespace wifislam::slam {
namespace {

using test::kPlaceA;
using test::kPlaceB;
using test::scan_of;

/// A minimal front end unlike RGBD-SLAM: every earlier keyframe of a similar cluster is a
/// candidate (exhaustive bounded search), only the best loop hypothesis is accepted.
class BoundedExhaustiveFrontEnd final : public frontend::FrontEnd {
 public:
  BoundedExhaustiveFrontEnd()
      : frontend::FrontEnd("bounded_exhaustive_test",
                           std::make_unique<frontend::AcceptBestLoopHypothesis>()) {}
  std::vector<frontend::Candidate> select(const frontend::SelectionQuery& query) override {
    std::vector<graph::KeyframeId> earlier;
    for (graph::KeyframeId k = 0; k < query.keyframe; ++k) earlier.push_back(k);
    std::vector<frontend::Candidate> out;
    for (graph::KeyframeId k : wifi()->bound(earlier))
      out.push_back({k, frontend::CandidateRole::kLongTerm});
    return out;
  }
};

/// One scripted walk: 0..19 at A, 20..39 at B, 40..49 back at A, where keyframe 45 matches
/// keyframe 5 (a loop edge). Every keyframe is tracked from its predecessor except 20 and 40
/// (tracking lost when the place changed).
struct Walk {
  struct Step {
    std::optional<WifiScan> scan;  // before the keyframe
    frontend::VerificationReport report;
  };
  std::vector<Step> steps;
};

Walk scripted_walk() {
  Walk walk;
  for (graph::KeyframeId k = 0; k < 50; ++k) {
    Walk::Step step;
    if (k == 0) step.scan = scan_of(0, kPlaceA);
    if (k == 20) step.scan = scan_of(100, kPlaceB);
    if (k == 40) step.scan = scan_of(200, kPlaceA);
    step.report.keyframe = k;
    step.report.tracked_from = (k == 0 || k == 20 || k == 40) ? -1 : k - 1;
    if (k == 45) {
      step.report.comparisons.push_back(
          {{5, frontend::CandidateRole::kLongTerm}, true, true, 60, graph::EdgeType::kLoop});
    }
    walk.steps.push_back(step);
  }
  return walk;
}

/// Drives `front_end` (holding `module`) over the walk as the pipeline would.
std::string run_walk(frontend::FrontEnd& front_end, const Walk& walk) {
  graph::PoseGraph graph;
  for (const Walk::Step& step : walk.steps) {
    if (step.scan) front_end.observe_wifi_scan(*step.scan);
    const graph::KeyframeId id = graph.add_node(Timestamp::from_ns(graph.node_count()),
                                                graph.node_count(), Pose::Identity());
    if (step.report.tracked_from >= 0) graph.add_edge({step.report.tracked_from, id});
    frontend::SelectionQuery query;
    query.keyframe = id;
    query.graph = &graph;
    frontend::LoopRule rule(15, 0.0);
    for (graph::KeyframeId k = 0; k <= id; ++k) rule.add_keyframe(static_cast<double>(k));
    query.loop_rule = &rule;
    front_end.candidates_for(query);
    front_end.on_verified(step.report);
  }
  return front_end.wifi()->clusters().to_csv();
}

TEST(WifiModule, SameInputsGiveTheSameClustersUnderTwoDifferentFrontEnds) {
  util::Instrumentation inst_a, inst_b;
  wifi::WifiOptions options;
  options.enabled = true;
  frontend::rgbdslam::RgbdslamFrontEnd rgbdslam(frontend::rgbdslam::RgbdslamOptions{}, 3);
  rgbdslam.attach_wifi(std::make_unique<wifi::WifiModule>(options, inst_a));
  BoundedExhaustiveFrontEnd other;
  other.attach_wifi(std::make_unique<wifi::WifiModule>(options, inst_b));
  std::vector<wifi::ClusterEvent> events;
  other.wifi()->subscribe([&](const wifi::ClusterEvent& e) { events.push_back(e); });

  const Walk walk = scripted_walk();
  const std::string a = run_walk(rgbdslam, walk);
  const std::string b = run_walk(other, walk);
  EXPECT_EQ(a, b);
  // A founds cluster 0 (keyframes 0..19), B cluster 1; back at A, keyframe 40 lost tracking and
  // has no edge into cluster 0, so it founds cluster 2; 41..44 join it, and 45, with a loop
  // edge into cluster 0 and tracking edge into cluster 2, joins the more similar (cluster 0 is
  // represented by the same signature, similarity 1; ties go to the lower id).
  const wifi::WifiClusterMap& clusters = other.wifi()->clusters();
  ASSERT_EQ(clusters.clusters().size(), 3u);
  EXPECT_EQ(clusters.cluster_of(19), 0);
  EXPECT_EQ(clusters.cluster_of(20), 1);
  EXPECT_EQ(clusters.cluster_of(40), 2);
  EXPECT_EQ(clusters.cluster_of(45), 0);
  // One event per clustered keyframe, three of them foundings.
  EXPECT_EQ(events.size(), 50u);
  EXPECT_EQ(std::count_if(events.begin(), events.end(),
                          [](const wifi::ClusterEvent& e) {
                            return e.kind == wifi::ClusterEvent::Kind::kFounded;
                          }),
            3);
  EXPECT_EQ(inst_b.counter(counter::kWifiClustersFounded), 3);
  EXPECT_EQ(inst_b.counter(counter::kWifiClusterJoins), 47);
}

TEST(WifiModule, BoundingImmunisationAndRetrievalAnswerFromTheSimilarClusters) {
  util::Instrumentation inst;
  wifi::WifiModule wifi(wifi::WifiOptions{}, inst);
  wifi.observe_scan(scan_of(0, kPlaceA));
  for (graph::KeyframeId k = 0; k < 10; ++k) {
    wifi.sign(k);
    wifi.assign(k,
                k > 0 ? std::vector<graph::KeyframeId>{k - 1} : std::vector<graph::KeyframeId>{});
  }
  wifi.observe_scan(scan_of(100, kPlaceB));
  for (graph::KeyframeId k = 10; k < 20; ++k) {
    wifi.sign(k);
    wifi.assign(k,
                k > 10 ? std::vector<graph::KeyframeId>{k - 1} : std::vector<graph::KeyframeId>{});
  }
  ASSERT_EQ(wifi.clusters().clusters().size(), 2u);

  wifi.observe_scan(scan_of(200, kPlaceA));
  wifi.sign(20);
  ASSERT_TRUE(wifi.has_signature());
  ASSERT_EQ(wifi.similar_clusters().size(), 1u);
  EXPECT_EQ(wifi.similar_clusters()[0].cluster, 0);
  EXPECT_EQ(wifi.bound({19, 3, 12, 7}), (std::vector<graph::KeyframeId>{3, 7}));
  EXPECT_TRUE(wifi.in_similar_cluster(9));
  EXPECT_FALSE(wifi.in_similar_cluster(10));
  EXPECT_FALSE(wifi.in_similar_cluster(20));  // not yet assigned
  std::vector<graph::KeyframeId> expected;
  for (graph::KeyframeId k = 0; k < 10; ++k) expected.push_back(k);
  EXPECT_EQ(wifi.similar_cluster_keyframes(), expected);
  EXPECT_EQ(wifi.assign(20, {9}), 0);
}

TEST(WifiModule, AKeyframeBeforeTheFirstScanIsUnboundedAndJoinsNoCluster) {
  util::Instrumentation inst;
  wifi::WifiModule wifi(wifi::WifiOptions{}, inst);
  wifi.sign(0);
  EXPECT_FALSE(wifi.has_signature());
  EXPECT_EQ(wifi.bound({}), std::vector<graph::KeyframeId>{});
  wifi.sign(1);
  EXPECT_EQ(wifi.bound({0}), std::vector<graph::KeyframeId>{0});
  EXPECT_EQ(wifi.assign(1, {0}), -1);
  EXPECT_EQ(inst.counter(counter::kWifiUnsignedKeyframes), 2);
  EXPECT_TRUE(wifi.clusters().clusters().empty());
}

TEST(WifiModule, KeyframesAreSignedInOrderAndAssignedOnce) {
  util::Instrumentation inst;
  wifi::WifiModule wifi(wifi::WifiOptions{}, inst);
  wifi.observe_scan(scan_of(0, kPlaceA));
  wifi.sign(3);
  EXPECT_THROW(wifi.sign(2), InvalidInputError);
  EXPECT_THROW(wifi.assign(2, {}), std::logic_error);
  EXPECT_EQ(wifi.assign(3, {}), 0);
  EXPECT_THROW(wifi.assign(3, {}), std::logic_error);
}

TEST(WifiModule, EveryRegisteredFrontEndGetsTheModuleWhenWifiIsOn) {
  frontend::register_front_end("bounded_exhaustive_test", [](const frontend::FrontEndContext&) {
    return std::make_unique<BoundedExhaustiveFrontEnd>();
  });
  util::Instrumentation inst;
  SlamOptions options;
  options.wifi.enabled = true;
  for (const std::string& name : frontend::front_end_names()) {
    options.frontend = name;
    const std::unique_ptr<frontend::FrontEnd> front_end =
        frontend::make_front_end({&options, &inst, /*stream_has_wifi=*/true, false});
    EXPECT_EQ(front_end->name(), name);
    ASSERT_NE(front_end->wifi(), nullptr) << name;
    EXPECT_EQ(front_end->label(), name + "+wifi");
    // Without scans in the stream, Wi-Fi is refused with a message that says why.
    try {
      frontend::make_front_end({&options, &inst, /*stream_has_wifi=*/false, false});
      ADD_FAILURE() << name << ": Wi-Fi accepted without scans";
    } catch (const InvalidInputError& e) {
      EXPECT_NE(std::string(e.what()).find("wifi.csv"), std::string::npos) << e.what();
    }
  }
  options.wifi.enabled = false;
  options.frontend = "rgbdslam";
  EXPECT_EQ(frontend::make_front_end({&options, &inst, true, false})->wifi(), nullptr);
}

}  // namespace
}  // namespace wifislam::slam
