// The robust back end on synthetic graphs: RGBDSLAMv2-style after-run pruning with the Huber
// kernel, bridges discounted instead of removed, and Ceres' verdict checked before poses change.

#include <gtest/gtest.h>

#include <cmath>
#include <deque>
#include <limits>
#include <numbers>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "slam/frontend/rgbdslam/rgbdslam_front_end.hpp"
#include "slam/graph/pose_graph.hpp"
#include "slam/optimize/edge_pruning.hpp"
#include "slam/optimize/pose_graph_optimizer.hpp"
#include "tests/slam/graph/graph_test_poses.hpp"

namespace wifislam::slam {
namespace {

constexpr double kSigmaM = 0.02, kSigmaRad = 0.01;

using test::information;
using test::planar;

/// A measurement of `truth` with the noise its information claims (translation sigma_m per axis,
/// rotation sigma_rad per axis, in the residual's convention), so its chi^2 follows chi^2(6).
Pose measure(const Pose& truth, Rng& rng) {
  Pose noise = Pose::Identity();
  noise.translation() =
      Eigen::Vector3d(rng.normal(0, kSigmaM), rng.normal(0, kSigmaM), rng.normal(0, kSigmaM));
  const Eigen::Vector3d axis_angle(rng.normal(0, kSigmaRad), rng.normal(0, kSigmaRad),
                                   rng.normal(0, kSigmaRad));
  noise.linear() = Eigen::AngleAxisd(axis_angle.norm(), axis_angle.normalized()).toRotationMatrix();
  Pose out = truth;
  out.translation() += noise.translation();
  out.linear() = truth.linear() * noise.linear();
  return out;
}

/// Every node reachable from node 0 through edges that were not pruned.
bool connected(const graph::PoseGraph& graph) {
  std::vector<char> seen(graph.node_count(), 0);
  std::deque<graph::KeyframeId> queue{0};
  seen[0] = 1;
  std::size_t reached = 1;
  while (!queue.empty()) {
    const graph::KeyframeId n = queue.front();
    queue.pop_front();
    for (const graph::GraphEdge& e : graph.edges()) {
      if (e.pruned || (e.from != n && e.to != n)) continue;
      const graph::KeyframeId m = e.from == n ? e.to : e.from;
      if (seen[static_cast<std::size_t>(m)]) continue;
      seen[static_cast<std::size_t>(m)] = 1;
      ++reached;
      queue.push_back(m);
    }
  }
  return reached == graph.node_count();
}

TEST(EdgePruning, RgbdslamScheduleRemovesAPlantedFalseLoopKeepsTrueEdgesAndTheGraphWhole) {
  // A 10 x 10 m square walked twice (160 poses, 0.5 m apart): sequential and skip-one visual
  // edges, and on the second lap a loop edge back to the same place on the first lap, all
  // measured with the noise their information claims. One false loop says pose 30 (middle of the
  // second side) is pose 70 (middle of the fourth), the look-alike corridor across the square.
  std::vector<Pose> truth;
  for (int lap = 0; lap < 2; ++lap) {
    double x = 0, y = 0, yaw = 0;
    for (int side = 0; side < 4; ++side) {
      for (int step = 0; step < 20; ++step) {
        truth.push_back(planar(x, y, yaw));
        x += 0.5 * std::cos(yaw);
        y += 0.5 * std::sin(yaw);
      }
      yaw += std::numbers::pi / 2;
    }
  }
  Rng rng = Rng::stream(5, "test/edge_pruning/measurements");
  graph::PoseGraph graph;
  Pose chained = truth[0];
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (i > 0) {
      const Pose m = measure(truth[i - 1].inverse() * truth[i], rng);
      chained = chained * m;
    }
    graph.add_node(Timestamp::from_ns(static_cast<std::int64_t>(i)), static_cast<std::int64_t>(i),
                   chained);
  }
  const auto add = [&](std::size_t a, std::size_t b, graph::EdgeType type) {
    graph.add_edge({static_cast<graph::KeyframeId>(a), static_cast<graph::KeyframeId>(b), type,
                    measure(truth[a].inverse() * truth[b], rng), information(kSigmaM, kSigmaRad),
                    100});
  };
  for (std::size_t i = 1; i < truth.size(); ++i) add(i - 1, i, graph::EdgeType::kVisual);
  for (std::size_t i = 2; i < truth.size(); ++i) add(i - 2, i, graph::EdgeType::kVisual);
  for (std::size_t i = 80; i < truth.size(); i += 4) add(i - 80, i, graph::EdgeType::kLoop);
  const std::size_t true_edges = graph.edges().size();
  graph::PoseGraph without_false_loop = graph;
  graph.add_edge({30, 110, graph::EdgeType::kLoop, truth[30].inverse() * truth[70],
                  information(kSigmaM, kSigmaRad), 60});

  const frontend::GraphRobustness robustness =
      frontend::rgbdslam::RgbdslamFrontEnd({}, 1).schedule().robustness;
  ASSERT_EQ(robustness.kernel.kind, optimize::RobustKernel::Kind::kHuber);
  ASSERT_TRUE(robustness.kernel.every_edge);
  ASSERT_EQ(robustness.pruning.chi2_thresholds.size(), 3u);
  int reoptimisations = 0;
  const auto reoptimise = [&](graph::PoseGraph& g) {
    ++reoptimisations;
    return optimize::optimise_pose_graph(g, optimize::PoseGraphOptions{}, 100, robustness.kernel);
  };
  ASSERT_TRUE(reoptimise(graph).usable);
  const double false_chi2 = optimize::edge_chi2(graph, graph.edges().back());
  const std::vector<optimize::PruningStage> stages =
      optimize::prune_inconsistent_edges(graph, robustness.pruning, reoptimise);

  ASSERT_EQ(stages.size(), 3u);
  EXPECT_TRUE(graph.edges().back().pruned) << "false loop chi^2 " << false_chi2;
  int true_pruned = 0;
  for (std::size_t e = 0; e < true_edges; ++e) true_pruned += graph.edges()[e].pruned ? 1 : 0;
  EXPECT_EQ(true_pruned, 0);
  EXPECT_EQ(stages[0].pruned, 1);  // the false loop goes at the first, loosest stage
  EXPECT_TRUE(stages[0].optimisation.ran && stages[0].optimisation.usable);
  EXPECT_TRUE(connected(graph));
  // With the false loop gone, the map is what the true edges alone give (within 1 cm), not the
  // metres-off map the false loop pulled it to.
  ASSERT_TRUE(reoptimise(without_false_loop).usable);
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const graph::KeyframeId id = static_cast<graph::KeyframeId>(i);
    EXPECT_LT(translation_distance_m(graph.node(id).pose, without_false_loop.node(id).pose), 0.01)
        << "pose " << i;
  }
  // The correct edges' chi^2 at the optimum is at or below chi^2(6)'s mean.
  double sum = 0.0;
  for (std::size_t e = 0; e < true_edges; ++e) sum += optimize::edge_chi2(graph, graph.edges()[e]);
  EXPECT_LT(sum / static_cast<double>(true_edges), 6.0);
}

TEST(EdgePruning, ABridgeIsDiscountedNotRemovedAndTheWorstOfAPairGoesFirst) {
  // Nodes 0-1-2 form a triangle whose 0-2 edge contradicts the other two; 2-3 is the only link
  // to node 3 and also contradicts the poses (nothing was optimised yet).
  graph::PoseGraph graph;
  for (int i = 0; i < 4; ++i) graph.add_node(Timestamp::from_ns(i), i, planar(i, 0, 0));
  const graph::Information6 info = information(kSigmaM, kSigmaRad);
  graph.add_edge({0, 1, graph::EdgeType::kVisual, planar(1, 0, 0), info, 50});
  graph.add_edge({1, 2, graph::EdgeType::kVisual, planar(1, 0, 0), info, 50});
  graph.add_edge({0, 2, graph::EdgeType::kLoop, planar(3, 0, 0), info, 50});
  graph.add_edge({2, 3, graph::EdgeType::kVisual, planar(0.5, 0, 0), info, 50});
  graph.add_edge({0, 3, graph::EdgeType::kOdometry, planar(9, 0, 0), info, 0});  // never pruned
  graph.prune_edge(4);  // ... unless already out: odometry marked pruned does not connect
  optimize::PruningSchedule schedule;
  schedule.chi2_thresholds = {10.0};
  int calls = 0;
  const std::vector<optimize::PruningStage> stages =
      optimize::prune_inconsistent_edges(graph, schedule, [&](graph::PoseGraph&) {
        ++calls;
        return optimize::OptimisationSummary{};
      });
  ASSERT_EQ(stages.size(), 1u);
  EXPECT_EQ(stages[0].pruned, 1);
  EXPECT_EQ(stages[0].discounted, 1);
  EXPECT_EQ(calls, 1);
  EXPECT_TRUE(graph.edges()[2].pruned);   // the contradicting triangle edge
  EXPECT_FALSE(graph.edges()[0].pruned);  // the two that agree with the poses stay
  EXPECT_FALSE(graph.edges()[1].pruned);
  EXPECT_FALSE(graph.edges()[3].pruned);  // the bridge stays, discounted
  EXPECT_DOUBLE_EQ(graph.edges()[3].weight, schedule.discount_weight);
  EXPECT_LT(optimize::edge_chi2(graph, graph.edges()[3]), 1e-3);
}

TEST(EdgePruning, NothingOverTheThresholdMeansNoReoptimisation) {
  graph::PoseGraph graph;
  for (int i = 0; i < 3; ++i) graph.add_node(Timestamp::from_ns(i), i, planar(i, 0, 0));
  graph.add_edge(
      {0, 1, graph::EdgeType::kVisual, planar(1, 0, 0), information(kSigmaM, kSigmaRad), 50});
  graph.add_edge(
      {1, 2, graph::EdgeType::kVisual, planar(1, 0, 0), information(kSigmaM, kSigmaRad), 50});
  optimize::PruningSchedule schedule;
  schedule.chi2_thresholds = {5.0, 1.0, 0.25};
  int calls = 0;
  const auto stages = optimize::prune_inconsistent_edges(graph, schedule, [&](graph::PoseGraph&) {
    ++calls;
    return optimize::OptimisationSummary{};
  });
  EXPECT_EQ(stages.size(), 3u);
  EXPECT_EQ(calls, 0);
  for (const graph::GraphEdge& e : graph.edges()) EXPECT_FALSE(e.pruned);
}

TEST(PoseGraphOptimiser, KeepsThePosesWhenCeresCannotUseItsSolution) {
  graph::PoseGraph graph;
  for (int i = 0; i < 3; ++i) graph.add_node(Timestamp::from_ns(i), i, planar(i, 0, 0));
  Pose broken = planar(1, 0, 0);
  broken.translation().x() = std::numeric_limits<double>::quiet_NaN();
  graph.add_edge(
      {0, 1, graph::EdgeType::kVisual, planar(1.5, 0, 0), information(kSigmaM, kSigmaRad)});
  graph.add_edge({1, 2, graph::EdgeType::kVisual, broken, information(kSigmaM, kSigmaRad)});
  const graph::PoseGraph before = graph;
  const optimize::OptimisationSummary summary =
      optimize::optimise_pose_graph(graph, optimize::PoseGraphOptions{}, 50);
  EXPECT_TRUE(summary.ran);
  EXPECT_FALSE(summary.usable) << summary.termination;
  EXPECT_FALSE(summary.termination.empty());
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(graph.node(i).pose.isApprox(before.node(i).pose)) << i;
  }
}

TEST(PoseGraphOptimiser, PrunedEdgesAreLeftOutAndWeightsScaleInformation) {
  // Two contradicting edges between the same nodes: the optimum sits between them, by weight.
  graph::PoseGraph graph;
  graph.add_node(Timestamp::from_ns(0), 0, Pose::Identity());
  graph.add_node(Timestamp::from_ns(1), 1, Pose::Identity());
  const graph::Information6 info = information(kSigmaM, kSigmaRad);
  graph.add_edge({0, 1, graph::EdgeType::kVisual, planar(1, 0, 0), info});
  graph.add_edge({0, 1, graph::EdgeType::kLoop, planar(2, 0, 0), info});
  graph.set_edge_weight(1, 3.0);  // x = (1 * 1 + 3 * 2) / 4
  optimize::optimise_pose_graph(graph, optimize::PoseGraphOptions{}, 50);
  EXPECT_NEAR(graph.node(1).pose.translation().x(), 1.75, 1e-3);
  graph.prune_edge(1);
  optimize::optimise_pose_graph(graph, optimize::PoseGraphOptions{}, 50);
  EXPECT_NEAR(graph.node(1).pose.translation().x(), 1.0, 1e-3);
}

}  // namespace
}  // namespace wifislam::slam
