// RTAB-Map's memory and Bayes filter through the real front end, on synthetic nodes: STM never
// searched, every node in exactly one memory, WM bounded under a tight time threshold, Wi-Fi
// immunisation and retrieval, posterior normalisation, and a revisit found by the filter.

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <set>

#include "core/error.hpp"
#include "slam/frontend/rtabmap/bayes_filter.hpp"
#include "tests/slam/frontend/rtabmap/rtabmap_test_nodes.hpp"

namespace wifislam::slam {
namespace {

using frontend::rtabmap::MemoryPlace;

void expect_partition(const frontend::rtabmap::RtabmapFrontEnd& fe, std::size_t nodes) {
  std::set<graph::KeyframeId> seen;
  const frontend::rtabmap::NodeMemory& m = fe.memory();
  for (graph::KeyframeId k : m.stm()) EXPECT_TRUE(seen.insert(k).second) << k;
  for (graph::KeyframeId k : m.wm()) EXPECT_TRUE(seen.insert(k).second) << k;
  for (graph::KeyframeId k : m.ltm()) EXPECT_TRUE(seen.insert(k).second) << k;
  EXPECT_EQ(seen.size(), nodes);
}

TEST(RtabmapMemory, StmNodesAreNeverLoopCandidatesAndEveryNodeIsInOneMemory) {
  // Only nodes that verify a loop closure go over budget: transfers start on the second lap.
  frontend::rtabmap::RtabmapOptions options;
  options.cost.ms_per_node = 0.0;
  options.cost.ms_per_word_comparison = 0.0;
  options.cost.ms_per_verification = 10.0;
  options.time_threshold_ms = 5.0;
  test::RtabmapDriver d(options);
  // Two laps over the same 30 places: plenty of loop-closure candidates on the second.
  int long_term = 0;
  for (int lap = 0; lap < 2; ++lap) {
    for (int p = 0; p < 30; ++p) {
      const std::vector<frontend::Candidate> c = d.select_only(p);
      for (const frontend::Candidate& x : c) {
        if (x.role != frontend::CandidateRole::kLongTerm) continue;
        ++long_term;
        EXPECT_EQ(d.front_end().memory().place(x.keyframe), MemoryPlace::kWm) << x.keyframe;
      }
      d.finish_node();
      expect_partition(d.front_end(), static_cast<std::size_t>(d.last() + 1));
      EXPECT_LE(d.front_end().memory().stm().size(), 10u);
    }
  }
  EXPECT_GT(long_term, 0);
  EXPECT_GT(d.front_end().memory().ltm().size(), 0u);
}

TEST(RtabmapMemory, WorkingMemoryStaysBoundedUnderATightThreshold) {
  frontend::rtabmap::RtabmapOptions tight;
  tight.time_threshold_ms = 1.0;  // every node is over budget (the fixed cost alone is 3.6 ms)
  test::RtabmapDriver bounded(tight);
  test::RtabmapDriver unbounded;
  std::size_t max_wm = 0;
  for (int p = 0; p < 80; ++p) {
    bounded.add_node(p);
    unbounded.add_node(p);
    max_wm = std::max(max_wm, bounded.front_end().memory().wm().size());
    EXPECT_LE(bounded.front_end().records().back().transferred,
              bounded.front_end().records().back().entered_wm + 1);
  }
  EXPECT_EQ(unbounded.front_end().memory().wm().size(), 70u);  // 80 - STM
  EXPECT_TRUE(unbounded.front_end().memory().ltm().empty());
  // What stays: the node linked to STM, the best hypothesis and its retrieval neighbourhood.
  EXPECT_LE(max_wm, 30u);
  EXPECT_GT(bounded.front_end().memory().ltm().size(), 40u);
  for (const frontend::rtabmap::RtabmapNodeRecord& r : bounded.front_end().records()) {
    EXPECT_GT(r.over_budget_ms, 0.0);
    EXPECT_EQ(r.stm + r.wm + r.ltm, static_cast<std::size_t>(r.node + 1));
  }
}

TEST(RtabmapMemory, RetrievalBringsBackAtMostMaxRetrievedNeighboursOfTheBestHypothesis) {
  frontend::rtabmap::RtabmapOptions tight;
  tight.time_threshold_ms = 1.0;
  test::RtabmapDriver d(tight);
  for (int p = 0; p < 60; ++p) d.add_node(p);
  int retrieved = 0;
  for (int p = 0; p < 20; ++p) {
    d.add_node(p);
    const frontend::rtabmap::RtabmapNodeRecord& r = d.front_end().records().back();
    EXPECT_LE(r.retrieved, tight.max_retrieved);
    retrieved += r.retrieved;
  }
  EXPECT_GT(retrieved, 0);
}

const std::vector<std::pair<std::uint64_t, int>> kPlaceA = {{0x10, -40}, {0x20, -60}, {0x30, -90}};
const std::vector<std::pair<std::uint64_t, int>> kPlaceB = {{0x10, -90}, {0x20, -60}, {0x30, -40}};

TEST(RtabmapWifi, ImmuneNodesAreNeverTransferredAndRetrievedNodesAreSearchedInTheSameStep) {
  frontend::rtabmap::RtabmapOptions tight;
  tight.time_threshold_ms = 1.0;
  test::RtabmapDriver d(tight, /*wifi=*/true);
  frontend::rtabmap::RtabmapFrontEnd& fe = d.front_end();
  const auto add_checked = [&](int place) {
    d.add_node(place);
    for (graph::KeyframeId k : fe.last_transferred()) {
      EXPECT_FALSE(fe.wifi()->in_similar_cluster(k)) << "immune node " << k << " transferred";
    }
  };
  fe.observe_wifi_scan(test::scan_at(0, kPlaceA));
  for (int p = 0; p < 40; ++p) add_checked(p);  // nodes 0..39 at A
  EXPECT_GT(fe.records().back().immune, 0);
  fe.observe_wifi_scan(test::scan_at(100, kPlaceB));
  for (int p = 40; p < 80; ++p) add_checked(p);  // 40..79 at B: A's nodes become transferable
  std::set<graph::KeyframeId> a_in_ltm;
  for (graph::KeyframeId k : fe.memory().ltm()) {
    if (k < 40) a_in_ltm.insert(k);
  }
  ASSERT_FALSE(a_in_ltm.empty());

  // Back at A: A's LTM nodes come back to WM in the step that needs them, and are scored.
  fe.observe_wifi_scan(test::scan_at(200, kPlaceA));
  d.select_only(5);
  for (graph::KeyframeId k : a_in_ltm) {
    EXPECT_EQ(fe.memory().place(k), MemoryPlace::kWm) << k;
    EXPECT_TRUE(fe.searchable(k)) << k;
  }
  d.finish_node();
  const frontend::rtabmap::RtabmapNodeRecord& r = fe.records().back();
  // Wi-Fi retrieval brings back what the best hypothesis' neighbourhood did not already.
  EXPECT_GT(r.wifi_retrieved, 0);
  EXPECT_EQ(static_cast<std::size_t>(r.wifi_retrieved + r.retrieved), a_in_ltm.size());
  EXPECT_GE(r.scored, a_in_ltm.size());
  for (graph::KeyframeId k : fe.last_transferred()) EXPECT_GE(k, 40);
}

// Where Wi-Fi cannot tell places apart (one signature everywhere, like the open a_hall twin),
// every WM node is immune and WM grows past any threshold; wifi_max_immune caps immunity, and WM
// with it, at the nodes of the most similar clusters.
TEST(RtabmapWifi, ImmunityCapBoundsWorkingMemoryWhereEveryPlaceLooksAlikeOnWifi) {
  frontend::rtabmap::RtabmapOptions uncapped;
  uncapped.time_threshold_ms = 1.0;
  frontend::rtabmap::RtabmapOptions capped = uncapped;
  capped.wifi_max_immune = 15;
  test::RtabmapDriver all_immune(uncapped, /*wifi=*/true), bounded(capped, /*wifi=*/true);
  for (test::RtabmapDriver* d : {&all_immune, &bounded}) {
    d->front_end().observe_wifi_scan(test::scan_at(0, kPlaceA));
  }
  std::size_t max_wm = 0;
  for (int p = 0; p < 80; ++p) {
    all_immune.add_node(p);
    bounded.add_node(p);
    const frontend::rtabmap::RtabmapNodeRecord& r = bounded.front_end().records().back();
    EXPECT_LE(r.immune, capped.wifi_max_immune);
    max_wm = std::max(max_wm, r.wm);
  }
  EXPECT_EQ(all_immune.front_end().memory().wm().size(), 70u);  // nothing could move
  EXPECT_GT(all_immune.front_end().records().back().immune, 60);
  EXPECT_EQ(bounded.front_end().records().back().immune, capped.wifi_max_immune);
  // The cap plus what the threshold keeps without Wi-Fi (the bound of the test above).
  EXPECT_LE(max_wm, static_cast<std::size_t>(capped.wifi_max_immune) + 30u);
  EXPECT_GT(bounded.front_end().memory().ltm().size(), 20u);
}

// RGBD/ProximityBySpace: a node that comes back within RGBD/ProximityPathFilteringRadius (1 m) of
// a WM node, looking the same way, verifies it as a proximity candidate (the path's most likely
// node); nothing is proposed far from every node, among STM nodes, or with the switch off.
TEST(RtabmapProximity, ANodeBackNearAWorkingMemoryNodeVerifiesItAsAProximityCandidate) {
  const auto proximity_of = [](const std::vector<frontend::Candidate>& candidates) {
    std::vector<graph::KeyframeId> out;
    for (const frontend::Candidate& c : candidates) {
      if (c.role == frontend::CandidateRole::kProximity) out.push_back(c.keyframe);
    }
    return out;
  };
  frontend::rtabmap::RtabmapOptions options;
  options.loop_threshold = 1.0;  // no global loop candidate: proximity alone
  for (const bool on : {true, false}) {
    SCOPED_TRACE(on ? "proximity on" : "proximity off");
    options.proximity_by_space = on;
    test::RtabmapDriver d(options);
    for (int p = 0; p < 30; ++p) {  // x = 0 .. 14.5 m; nodes 20-29 are in STM
      EXPECT_TRUE(proximity_of(d.add_node(p)).empty()) << "node " << p;
    }
    // Back at node 6 (x = 3 m), seeing place 6 again, 0.2 m off.
    const std::vector<graph::KeyframeId> near = proximity_of(d.add_node(6, 3.2));
    if (on) {
      EXPECT_EQ(near, (std::vector<graph::KeyframeId>{6}));
    } else {
      EXPECT_TRUE(near.empty());
    }
    // Far from every node: nothing; next to an STM node (x = 13 m, node 26): nothing.
    EXPECT_TRUE(proximity_of(d.add_node(50, 100.0)).empty());
    EXPECT_TRUE(proximity_of(d.add_node(26, 13.1)).empty());
  }
}

TEST(RtabmapBayes, PosteriorSumsToOne) {
  test::RtabmapDriver d;
  for (int p = 0; p < 40; ++p) {
    d.add_node(p % 25);
    const auto& posterior = d.front_end().bayes_filter().posterior();
    if (posterior.empty()) continue;
    double sum = 0;
    for (const auto& [id, prob] : posterior) {
      EXPECT_GE(prob, 0.0);
      sum += prob;
    }
    EXPECT_NEAR(sum, 1.0, 1e-9) << p;
  }
}

TEST(RtabmapBayes, RevisitedPlaceRisesAboveTheLoopThresholdWithinAFewNodes) {
  test::RtabmapDriver d;
  for (int p = 0; p < 40; ++p) d.add_node(p);
  // Before the revisit no hypothesis reaches the threshold once WM has a few nodes: every place
  // is new. (With one or two WM nodes a node hypothesis holds a third of the posterior whatever
  // the likelihood says; RTAB-Map verifies and rejects such candidates.)
  for (const frontend::rtabmap::RtabmapNodeRecord& r : d.front_end().records()) {
    if (r.scored >= 5) {
      EXPECT_EQ(r.loop_candidate, -1) << "node " << r.node;
    }
  }
  int first_candidate = -1;
  for (int p = 0; p < 8; ++p) {
    const std::vector<frontend::Candidate> c = d.add_node(p);  // node 40 + p revisits node p
    const frontend::rtabmap::RtabmapNodeRecord& r = d.front_end().records().back();
    if (r.loop_candidate >= 0) {
      EXPECT_EQ(r.loop_candidate, p) << "node " << r.node;
      EXPECT_GE(r.best_probability, 0.11);
      EXPECT_NE(
          std::find(c.begin(), c.end(), frontend::Candidate{p, frontend::CandidateRole::kLongTerm}),
          c.end());
      if (first_candidate < 0) first_candidate = p;
    }
  }
  ASSERT_GE(first_candidate, 0);
  EXPECT_LE(first_candidate, 3);
}

TEST(RtabmapBayes, PredictionModelSpreadsProbabilityToGraphNeighbours) {
  // Two hypotheses 5 and 6, neighbours at margin 1; the last posterior all on 5.
  frontend::rtabmap::BayesFilter filter(
      frontend::rtabmap::parse_prediction_lc("bayes_prediction_lc",
                                             frontend::rtabmap::kDefaultPredictionLc),
      0.9);
  const auto neighbours = [](frontend::rtabmap::NodeId id, int) {
    return std::map<frontend::rtabmap::NodeId, int>{{id, 0}, {id == 5 ? 6 : 5, 1}};
  };
  filter.update({{5, 1.0}, {6, 1.0}}, 1.0, neighbours);  // uniform start
  filter.update({{5, 10.0}, {6, 1.0}}, 1.0, neighbours);
  const double p5 = filter.posterior().at(5), p6 = filter.posterior().at(6);
  EXPECT_GT(p5, p6);
  EXPECT_GT(p6, 0.0);
  EXPECT_EQ(filter.best().first, 5);
  EXPECT_NEAR(p5 + p6 + filter.virtual_probability(), 1.0, 1e-12);
  EXPECT_THROW(frontend::rtabmap::parse_prediction_lc("k", "0.1"), InvalidInputError);
  EXPECT_THROW(frontend::rtabmap::parse_prediction_lc("k", "0.1 x"), InvalidInputError);
}

}  // namespace
}  // namespace wifislam::slam
