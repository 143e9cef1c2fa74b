// RGBD-SLAM's candidate selection (predecessors, geodesic neighbours, random earlier keyframes)
// and the front-end seam.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "core/error.hpp"
#include "slam/frontend/front_end_registry.hpp"
#include "slam/frontend/rgbdslam/rgbdslam_front_end.hpp"

namespace wifislam::slam {
namespace {

/// A chain of `n` keyframes plus a loop edge 0 - (n - 2).
graph::PoseGraph chain_with_loop(int n) {
  graph::PoseGraph graph;
  for (int i = 0; i < n; ++i) graph.add_node(Timestamp::from_ns(i), i, Pose::Identity());
  for (int i = 1; i < n; ++i) graph.add_edge({i - 1, i, graph::EdgeType::kVisual});
  graph.add_edge({0, n - 2, graph::EdgeType::kLoop});
  return graph;
}

frontend::SelectionQuery query_for(const graph::PoseGraph& graph, graph::KeyframeId id) {
  frontend::SelectionQuery q;
  q.keyframe = id;
  q.graph = &graph;
  q.already_compared = {id - 1};
  return q;
}

TEST(RgbdslamSelection, PredecessorsNeighboursAndRandomEarlierKeyframes) {
  const graph::PoseGraph graph = chain_with_loop(41);
  frontend::rgbdslam::RgbdslamFrontEnd selector(frontend::rgbdslam::RgbdslamOptions{}, 7);
  const std::vector<frontend::Candidate> c = selector.select(query_for(graph, 40));
  std::map<frontend::CandidateRole, std::vector<graph::KeyframeId>> by_role;
  for (const frontend::Candidate& x : c) by_role[x.role].push_back(x.keyframe);
  // Predecessors 39..36; 39 was compared by tracking, so 38, 37, 36 are returned.
  EXPECT_EQ(by_role[frontend::CandidateRole::kPredecessor],
            (std::vector<graph::KeyframeId>{38, 37, 36}));
  // Neighbours of 39 within depth 3, predecessors excluded: through the loop edge 0 - 39,
  // keyframes 0, 1, 2 (fewer than the 4 asked for, so all of them).
  std::vector<graph::KeyframeId> neighbours = by_role[frontend::CandidateRole::kNeighbour];
  std::sort(neighbours.begin(), neighbours.end());
  EXPECT_EQ(neighbours, (std::vector<graph::KeyframeId>{0, 1, 2}));
  ASSERT_EQ(by_role[frontend::CandidateRole::kLongTerm].size(), 4u);
  for (graph::KeyframeId k : by_role[frontend::CandidateRole::kLongTerm]) {
    EXPECT_GE(k, 3);
    EXPECT_LE(k, 35);
  }
  std::set<graph::KeyframeId> all;
  for (const frontend::Candidate& x : c) {
    EXPECT_LT(x.keyframe, 40);
    EXPECT_NE(x.keyframe, 39);
    EXPECT_TRUE(all.insert(x.keyframe).second) << "duplicate " << x.keyframe;
  }
}

TEST(RgbdslamSelection, SameSeedSameCandidatesOtherSeedOtherCandidates) {
  const graph::PoseGraph graph = chain_with_loop(200);
  auto run = [&](std::uint64_t seed) {
    frontend::rgbdslam::RgbdslamFrontEnd selector(frontend::rgbdslam::RgbdslamOptions{}, seed);
    std::vector<graph::KeyframeId> out;
    for (graph::KeyframeId id = 100; id < 199; ++id) {
      for (const frontend::Candidate& c : selector.select(query_for(graph, id)))
        out.push_back(c.keyframe);
    }
    return out;
  };
  EXPECT_EQ(run(3), run(3));
  EXPECT_NE(run(3), run(4));
}

TEST(RgbdslamSelection, RandomKeyframesCoverTheWholeMap) {
  // Uniform sampling: over many seeds every earlier keyframe gets picked.
  const graph::PoseGraph graph = chain_with_loop(60);
  frontend::rgbdslam::RgbdslamOptions options;
  options.neighbor_candidates = 0;
  options.predecessor_candidates = 2;
  std::set<graph::KeyframeId> seen;
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    frontend::rgbdslam::RgbdslamFrontEnd selector(options, seed);
    for (const frontend::Candidate& c : selector.select(query_for(graph, 50))) {
      if (c.role == frontend::CandidateRole::kLongTerm) seen.insert(c.keyframe);
    }
  }
  EXPECT_EQ(seen.size(), 48u);  // keyframes 0..47 (48 and 49 are predecessors)
}

TEST(RgbdslamSelection, NeighboursAreDrawnInProportionToTheirIdDistance) {
  // Keyframe 49 reaches 48..40 along the chain and, through a loop edge to 0, keyframes 0..8
  // (depth 10). With one predecessor (49, compared by tracking) and one neighbour drawn, the
  // far group's weights (49 - id: 49..41, sum 405) against the near group's (1..9, sum 45) give
  // it the draw 90 % of the time, as RGBDSLAMv2's getPotentialEdgeTargetsWithDijkstra does.
  graph::PoseGraph graph;
  for (int i = 0; i < 51; ++i) graph.add_node(Timestamp::from_ns(i), i, Pose::Identity());
  for (int i = 1; i < 51; ++i) graph.add_edge({i - 1, i, graph::EdgeType::kVisual});
  graph.add_edge({0, 49, graph::EdgeType::kLoop});
  frontend::rgbdslam::RgbdslamOptions options;
  options.predecessor_candidates = 1;
  options.neighbor_candidates = 1;
  options.geodesic_depth = 9;
  options.min_sampled_candidates = 0;
  int far = 0, near = 0;
  for (std::uint64_t seed = 0; seed < 2000; ++seed) {
    frontend::rgbdslam::RgbdslamFrontEnd selector(options, seed);
    for (const frontend::Candidate& c : selector.select(query_for(graph, 50))) {
      if (c.role != frontend::CandidateRole::kNeighbour) continue;
      (c.keyframe <= 8 ? far : near) += 1;
      EXPECT_TRUE(c.keyframe <= 8 || (c.keyframe >= 40 && c.keyframe <= 48)) << c.keyframe;
    }
  }
  EXPECT_EQ(far + near, 2000);
  EXPECT_NEAR(far / 2000.0, 0.9, 0.03);
}

TEST(RgbdslamSelection, EachKeyframeDrawsFromItsOwnSubStream) {
  // The draws for keyframe k do not depend on what was drawn for earlier keyframes: selecting
  // keyframe 150 alone gives what it gives after 100..149 were selected.
  const graph::PoseGraph graph = chain_with_loop(200);
  frontend::rgbdslam::RgbdslamFrontEnd alone(frontend::rgbdslam::RgbdslamOptions{}, 9);
  frontend::rgbdslam::RgbdslamFrontEnd after(frontend::rgbdslam::RgbdslamOptions{}, 9);
  for (graph::KeyframeId id = 100; id < 150; ++id) after.select(query_for(graph, id));
  EXPECT_EQ(alone.select(query_for(graph, 150)), after.select(query_for(graph, 150)));
}

TEST(RgbdslamSelection, FirstKeyframesGetWhatExists) {
  const graph::PoseGraph graph = chain_with_loop(3);
  frontend::rgbdslam::RgbdslamFrontEnd selector(frontend::rgbdslam::RgbdslamOptions{}, 1);
  frontend::SelectionQuery q;
  q.keyframe = 0;
  q.graph = &graph;
  EXPECT_TRUE(selector.select(q).empty());
  q.keyframe = 1;
  const auto c = selector.select(q);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].keyframe, 0);
}

/// A front end defined outside the library: the seam admits it without touching the pipeline.
class EveryKeyframeSelector : public frontend::FrontEnd {
 public:
  EveryKeyframeSelector()
      : frontend::FrontEnd("every_keyframe_test",
                           std::make_unique<frontend::AcceptAllHypotheses>()) {}
  std::vector<frontend::Candidate> select(const frontend::SelectionQuery& q) override {
    std::vector<frontend::Candidate> out;
    for (graph::KeyframeId k = 0; k < q.keyframe; ++k)
      out.push_back({k, frontend::CandidateRole::kLongTerm});
    return out;
  }
};

TEST(FrontEndRegistry, BuildsByNameAndRejectsUnknownNames) {
  SlamOptions options;
  util::Instrumentation instrumentation;
  frontend::FrontEndContext context{&options, &instrumentation, false, false};
  EXPECT_EQ(frontend::make_front_end(context)->name(), "rgbdslam");
  options.frontend = "no_such_frontend";
  try {
    frontend::make_front_end(context);
    FAIL() << "expected InvalidInputError";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("rgbdslam"), std::string::npos) << e.what();
  }
  frontend::register_front_end("every_keyframe_test", [](const frontend::FrontEndContext&) {
    return std::make_unique<EveryKeyframeSelector>();
  });
  options.frontend = "every_keyframe_test";
  EXPECT_EQ(frontend::make_front_end(context)->name(), "every_keyframe_test");
}

TEST(VerificationReport, ListsVisuallyConnectedKeyframes) {
  frontend::VerificationReport report;
  report.tracked_from = 9;
  report.comparisons = {
      {{8, frontend::CandidateRole::kPredecessor}, true, true, 50, graph::EdgeType::kVisual},
      {{2, frontend::CandidateRole::kLongTerm}, false, false, 0, graph::EdgeType::kVisual},
      {{5, frontend::CandidateRole::kLongTerm}, true, false, 40, graph::EdgeType::kLoop},
      {{1, frontend::CandidateRole::kLongTerm}, true, true, 30, graph::EdgeType::kLoop}};
  // Keyframe 5 passed verification but acceptance refused the edge: not connected.
  EXPECT_EQ(report.visually_connected(), (std::vector<graph::KeyframeId>{1, 8, 9}));
}

}  // namespace
}  // namespace wifislam::slam
