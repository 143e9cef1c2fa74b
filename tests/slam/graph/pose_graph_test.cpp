// Pose-graph optimisation with Ceres on synthetic graphs.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "slam/graph/pose_graph.hpp"
#include "slam/optimize/pose_graph_optimizer.hpp"
#include "tests/slam/graph/graph_test_poses.hpp"

namespace wifislam::slam {
namespace {

using test::information;
using test::planar;

/// Poses around a 10 x 10 m square, 0.5 m apart, turning at the corners; back at the start.
std::vector<Pose> square_loop() {
  std::vector<Pose> poses;
  double x = 0, y = 0, yaw = 0;
  for (int side = 0; side < 4; ++side) {
    for (int step = 0; step < 20; ++step) {
      poses.push_back(planar(x, y, yaw));
      x += 0.5 * std::cos(yaw);
      y += 0.5 * std::sin(yaw);
    }
    yaw += std::numbers::pi / 2;
  }
  poses.push_back(planar(x, y, yaw));  // == the first pose, a full turn later
  return poses;
}

Pose perturb(const Pose& p, Rng& rng, double sigma_m, double sigma_rad, double yaw_bias_rad) {
  Pose noise = Pose::Identity();
  noise.translation() =
      Eigen::Vector3d(rng.normal(0, sigma_m), rng.normal(0, sigma_m), rng.normal(0, sigma_m));
  const Eigen::Vector3d axis_angle(rng.normal(0, sigma_rad), rng.normal(0, sigma_rad),
                                   rng.normal(0, sigma_rad) + yaw_bias_rad);
  noise.linear() = Eigen::AngleAxisd(axis_angle.norm(), axis_angle.normalized()).toRotationMatrix();
  return p * noise;
}

TEST(PoseGraph, OneCorrectLoopClosureCutsEndPointErrorByAtLeastEightyPercent) {
  const std::vector<Pose> truth = square_loop();
  Rng rng = Rng::stream(11, "test/pose_graph/odometry");
  graph::PoseGraph graph;
  const double sigma_m = 0.02, sigma_rad = 0.01;
  Pose chained = truth[0];
  graph.add_node(Timestamp::from_ns(0), 0, chained);
  for (std::size_t i = 1; i < truth.size(); ++i) {
    // Noisy odometry with a systematic yaw bias, like wheel odometry drifting.
    const Pose measured =
        perturb(truth[i - 1].inverse() * truth[i], rng, sigma_m, sigma_rad, 0.004);
    chained = chained * measured;
    graph.add_node(Timestamp::from_ns(static_cast<std::int64_t>(i)), static_cast<std::int64_t>(i),
                   chained);
    graph.add_edge({static_cast<graph::KeyframeId>(i - 1), static_cast<graph::KeyframeId>(i),
                    graph::EdgeType::kOdometry, measured, information(sigma_m, sigma_rad), 0});
  }
  const graph::KeyframeId last = static_cast<graph::KeyframeId>(truth.size() - 1);
  // One correct loop closure: the last pose seen from the first, measured precisely.
  graph.add_edge({0, last, graph::EdgeType::kLoop, truth[0].inverse() * truth.back(),
                  information(0.005, 0.002), 40});

  const double before_m = translation_distance_m(graph.node(last).pose, truth.back());
  const optimize::OptimisationSummary summary =
      optimize::optimise_pose_graph(graph, optimize::PoseGraphOptions{}, 100);
  const double after_m = translation_distance_m(graph.node(last).pose, truth.back());
  std::printf("end-point error %.3f m -> %.3f m (%s)\n", before_m, after_m, summary.brief.c_str());
  ASSERT_TRUE(summary.ran);
  ASSERT_GT(before_m, 0.3);  // the drift is real
  EXPECT_LE(after_m, 0.2 * before_m);
  EXPECT_LT(summary.final_cost, summary.initial_cost);
  // The gauge: the first node does not move.
  EXPECT_TRUE(graph.node(0).pose.isApprox(truth[0], 1e-12));
}

TEST(PoseGraph, GaugeFixedChainWithoutLoopIsUnchanged) {
  const std::vector<Pose> truth = square_loop();
  Rng rng = Rng::stream(12, "test/pose_graph/chain");
  graph::PoseGraph graph;
  Pose chained = truth[0];
  graph.add_node(Timestamp::from_ns(0), 0, chained);
  for (std::size_t i = 1; i < 40; ++i) {
    const Pose measured = perturb(truth[i - 1].inverse() * truth[i], rng, 0.02, 0.01, 0.0);
    chained = chained * measured;
    graph.add_node(Timestamp::from_ns(static_cast<std::int64_t>(i)), static_cast<std::int64_t>(i),
                   chained);
    graph.add_edge({static_cast<graph::KeyframeId>(i - 1), static_cast<graph::KeyframeId>(i),
                    graph::EdgeType::kVisual, measured, information(0.02, 0.01), 100});
  }
  const graph::PoseGraph before = graph;
  optimize::optimise_pose_graph(graph, optimize::PoseGraphOptions{}, 100);
  for (std::size_t i = 0; i < graph.node_count(); ++i) {
    const graph::KeyframeId id = static_cast<graph::KeyframeId>(i);
    EXPECT_LT(translation_distance_m(graph.node(id).pose, before.node(id).pose), 1e-9) << i;
    EXPECT_LT(rotation_angle_rad(graph.node(id).pose, before.node(id).pose), 1e-9) << i;
  }
}

TEST(PoseGraph, RobustLossLimitsAFalseLoopClosure) {
  const std::vector<Pose> truth = square_loop();
  auto build = [&](graph::PoseGraph& graph) {
    for (std::size_t i = 0; i < truth.size(); ++i) {
      graph.add_node(Timestamp::from_ns(static_cast<std::int64_t>(i)), static_cast<std::int64_t>(i),
                     truth[i]);
      if (i > 0) {
        graph.add_edge({static_cast<graph::KeyframeId>(i - 1), static_cast<graph::KeyframeId>(i),
                        graph::EdgeType::kVisual, truth[i - 1].inverse() * truth[i],
                        information(0.01, 0.005), 100});
      }
    }
    // A false loop closure claiming node 30 is where node 70 is.
    graph.add_edge(
        {30, 70, graph::EdgeType::kLoop, Pose::Identity(), information(0.01, 0.005), 25});
  };
  graph::PoseGraph plain, robust;
  build(plain);
  build(robust);
  optimize::PoseGraphOptions options;
  optimize::optimise_pose_graph(plain, options, 100);
  optimize::RobustKernel cauchy;
  cauchy.kind = optimize::RobustKernel::Kind::kCauchy;
  optimize::optimise_pose_graph(robust, options, 100, cauchy);
  const double plain_error = translation_distance_m(plain.node(50).pose, truth[50]);
  const double robust_error = translation_distance_m(robust.node(50).pose, truth[50]);
  std::printf("mid-loop error with a false closure: plain %.3f m, cauchy %.3f m\n", plain_error,
              robust_error);
  EXPECT_GT(plain_error, 0.5);
  EXPECT_LT(robust_error, 0.5 * plain_error);
}

TEST(PoseGraph, GeodesicNeighboursByDistanceThenId) {
  graph::PoseGraph graph;
  for (int i = 0; i < 6; ++i) graph.add_node(Timestamp::from_ns(i), i, Pose::Identity());
  for (int i = 1; i < 6; ++i) graph.add_edge({i - 1, i, graph::EdgeType::kVisual});
  graph.add_edge({0, 5, graph::EdgeType::kLoop});
  EXPECT_EQ(graph.geodesic_neighbours(5, 1), (std::vector<graph::KeyframeId>{0, 4}));
  EXPECT_EQ(graph.geodesic_neighbours(5, 2), (std::vector<graph::KeyframeId>{0, 4, 1, 3}));
  EXPECT_TRUE(graph.has_edge(5, 0));
  EXPECT_FALSE(graph.has_edge(1, 3));
  EXPECT_THROW(graph.add_edge({2, 2, graph::EdgeType::kVisual}), InvalidInputError);
}

}  // namespace
}  // namespace wifislam::slam
