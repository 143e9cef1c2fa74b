// The front ends' acceptance policies: every hypothesis (RGBD-SLAM), the best loop hypothesis
// only (RTAB-Map, ORB-SLAM), and the graph-consistency check (RTAB-Map's RGBD/OptimizeMaxError)
// with a real Ceres solve: a loop closure that contradicts the rest of the graph is refused, one
// that agrees is kept.

#include <gtest/gtest.h>

#include "slam/frontend/edge_acceptance.hpp"

namespace wifislam::slam {
namespace {

graph::Information6 information(double sigma_m, double sigma_rad) {
  graph::Information6 info = graph::Information6::Zero();
  info.diagonal().head<3>().setConstant(1.0 / (sigma_m * sigma_m));
  info.diagonal().tail<3>().setConstant(1.0 / (sigma_rad * sigma_rad));
  return info;
}

Pose at_x(double x_m) {
  Pose p = Pose::Identity();
  p.translation().x() = x_m;
  return p;
}

/// Keyframes 0..10 walk east 1 m apart, 11..19 walk back west; keyframe 20 stands where 0 stood.
/// Every consecutive pair has an exact visual edge; keyframe 20 is tracked from 19.
graph::PoseGraph out_and_back() {
  graph::PoseGraph graph;
  std::vector<double> x;
  for (int i = 0; i <= 10; ++i) x.push_back(i);
  for (int i = 9; i >= 0; --i) x.push_back(i);
  for (std::size_t i = 0; i < x.size(); ++i) {
    graph.add_node(Timestamp::from_ns(static_cast<std::int64_t>(i)), static_cast<std::int64_t>(i),
                   at_x(x[i]));
  }
  for (graph::KeyframeId i = 1; i < static_cast<graph::KeyframeId>(x.size()); ++i) {
    graph.add_edge({i - 1, i, graph::EdgeType::kVisual, at_x(x[i - 1]).inverse() * at_x(x[i]),
                    information(0.05, 0.02), 100});
  }
  return graph;
}

frontend::Hypothesis hypothesis(graph::KeyframeId from, const Pose& from_to, graph::EdgeType type,
                                int inliers) {
  frontend::Hypothesis h;
  h.candidate = {from, type == graph::EdgeType::kLoop ? frontend::CandidateRole::kLongTerm
                                                      : frontend::CandidateRole::kPredecessor};
  h.transformation.accepted = true;
  h.transformation.a_from_b = from_to;
  h.transformation.inliers = inliers;
  h.transformation.information = information(0.05, 0.02);
  h.edge_type = type;
  return h;
}

TEST(EdgeAcceptance, AllKeepsEveryHypothesisInOrder) {
  const graph::PoseGraph graph = out_and_back();
  const std::vector<frontend::Hypothesis> h = {
      hypothesis(18, at_x(-2), graph::EdgeType::kVisual, 80),
      hypothesis(0, at_x(0), graph::EdgeType::kLoop, 40),
      hypothesis(5, at_x(0), graph::EdgeType::kLoop, 90)};
  EXPECT_EQ(frontend::AcceptAllHypotheses().choose(h, {&graph, 20, true, {}}),
            (std::vector<std::size_t>{0, 1, 2}));
}

TEST(EdgeAcceptance, BestKeepsVisualEdgesAndTheLoopHypothesisWithMostInliers) {
  const graph::PoseGraph graph = out_and_back();
  const std::vector<frontend::Hypothesis> h = {
      hypothesis(0, at_x(0), graph::EdgeType::kLoop, 40),
      hypothesis(18, at_x(-2), graph::EdgeType::kVisual, 80),
      hypothesis(5, at_x(0), graph::EdgeType::kLoop, 90),
      hypothesis(1, at_x(-1), graph::EdgeType::kLoop, 90)};
  EXPECT_EQ(frontend::AcceptBestLoopHypothesis().choose(h, {&graph, 20, true, {}}),
            (std::vector<std::size_t>{1, 2}));
}

TEST(EdgeAcceptance, GraphConsistencyRefusesAPlantedFalseLoopClosureAndKeepsTheTrueOne) {
  const graph::PoseGraph graph = out_and_back();
  const frontend::AcceptGraphConsistentHypotheses policy(
      std::make_unique<frontend::AcceptAllHypotheses>(), 3.0, optimize::PoseGraphOptions{}, 20);
  const frontend::Hypothesis truth = hypothesis(0, at_x(0), graph::EdgeType::kLoop, 60);
  // "Keyframe 20 stands where keyframe 5 stood": 5 m from where the chain puts it.
  const frontend::Hypothesis planted = hypothesis(5, at_x(0), graph::EdgeType::kLoop, 70);
  const frontend::Hypothesis visual = hypothesis(18, at_x(-2), graph::EdgeType::kVisual, 80);

  EXPECT_EQ(policy.choose({truth}, {&graph, 20, true, {}}), (std::vector<std::size_t>{0}));
  EXPECT_TRUE(policy.choose({planted}, {&graph, 20, true, {}}).empty());
  // Both: the false one is dropped, the true one and the ordinary visual edge stay.
  EXPECT_EQ(policy.choose({visual, planted, truth}, {&graph, 20, true, {}}),
            (std::vector<std::size_t>{0, 2}));
  // The input graph is not touched.
  EXPECT_EQ(graph.edges().size(), 20u);
}

TEST(EdgeAcceptance, AConfidentFalseLoopClosureIsCaughtByTheLinksItTears) {
  // The planted loop claims a hundred times the chain's certainty: after optimisation it is
  // nearly satisfied itself, and the chain edges carry the 5 m instead. Checking every link (as
  // RTAB-Map does) still refuses it.
  const graph::PoseGraph graph = out_and_back();
  const frontend::AcceptGraphConsistentHypotheses policy(
      std::make_unique<frontend::AcceptAllHypotheses>(), 3.0, optimize::PoseGraphOptions{}, 20);
  frontend::Hypothesis planted = hypothesis(5, at_x(0), graph::EdgeType::kLoop, 70);
  planted.transformation.information = information(0.005, 0.002);
  EXPECT_TRUE(policy.choose({planted}, {&graph, 20, true, {}}).empty());
}

TEST(EdgeAcceptance, WithTrackingLostTheLoopClosureMustAgreeWithOdometry) {
  // Keyframe 20 lost tracking: without odometry in the trial a lone false loop edge would hang
  // unopposed; with the odometry edge from keyframe 19 it is refused, and the true one kept.
  graph::PoseGraph graph = out_and_back();
  const frontend::AcceptGraphConsistentHypotheses policy(
      std::make_unique<frontend::AcceptAllHypotheses>(), 3.0, optimize::PoseGraphOptions{}, 20);
  graph::PoseGraph lost;
  for (const graph::GraphNode& n : graph.nodes()) lost.add_node(n.time, n.frame_index, n.pose);
  for (const graph::GraphEdge& e : graph.edges()) {
    if (e.to != 20) lost.add_edge(e);
  }
  const graph::GraphEdge odometry{
      19, 20, graph::EdgeType::kOdometry, at_x(-1), information(0.05, 0.02), 0};
  const frontend::Hypothesis planted = hypothesis(5, at_x(0), graph::EdgeType::kLoop, 70);
  const frontend::Hypothesis truth = hypothesis(0, at_x(0), graph::EdgeType::kLoop, 60);
  EXPECT_EQ(policy.choose({planted}, {&lost, 20, false, {}}), (std::vector<std::size_t>{0}));
  EXPECT_TRUE(policy.choose({planted}, {&lost, 20, false, {odometry}}).empty());
  EXPECT_EQ(policy.choose({truth}, {&lost, 20, false, {odometry}}), (std::vector<std::size_t>{0}));
}

TEST(EdgeAcceptance, ErrorRatioIsTheErrorInStandardDeviationsOfTheEdge) {
  graph::PoseGraph graph;
  graph.add_node(Timestamp::from_ns(0), 0, Pose::Identity());
  graph.add_node(Timestamp::from_ns(1), 1, at_x(1.2));
  // Measured 1.0 m with sigma 0.1 m: 0.2 m off = 2 standard deviations.
  EXPECT_NEAR(frontend::edge_error_ratio(
                  graph, {0, 1, graph::EdgeType::kLoop, at_x(1.0), information(0.1, 0.01)})
                  .value(),
              2.0, 1e-6);
  // The largest translation variance counts: sigma 0.1 m along x, 0.4 m along y.
  graph::Information6 anisotropic = information(0.1, 0.01);
  anisotropic(1, 1) = 1.0 / (0.4 * 0.4);
  EXPECT_NEAR(
      frontend::edge_error_ratio(graph, {0, 1, graph::EdgeType::kLoop, at_x(1.0), anisotropic})
          .value(),
      0.5, 1e-6);
  // Coupled translation and rotation (a sideways shift y and a yaw explain the same image
  // motion): the information's diagonal is large, but the marginal standard deviation of y, from
  // the covariance, is what the error is measured against. Covariance: sigma_x = sigma_z = 0.01
  // m, sigma_y 0.1 m, sigma_yaw 0.01 rad, y-yaw correlation 0.999; 1 / the information diagonal
  // would say sigma_y = 0.1 * sqrt(1 - 0.999^2) and make the error 20 standard deviations.
  graph::Information6 coupled_covariance = graph::Information6::Zero();
  coupled_covariance.diagonal() << 1e-4, 0.01, 1e-4, 1e-4, 1e-4, 1e-4;
  coupled_covariance(1, 5) = coupled_covariance(5, 1) = 0.999 * 0.1 * 0.01;
  graph::PoseGraph sideways;
  sideways.add_node(Timestamp::from_ns(0), 0, Pose::Identity());
  Pose off = at_x(1.0);
  off.translation().y() = 0.2;  // 0.2 m off along y = 2 marginal standard deviations
  sideways.add_node(Timestamp::from_ns(1), 1, off);
  EXPECT_NEAR(
      frontend::edge_error_ratio(sideways, {0, 1, graph::EdgeType::kLoop, at_x(1.0),
                                            graph::Information6(coupled_covariance.inverse())})
          .value(),
      2.0, 1e-6);
  // Links RTAB-Map skips: translation variance above 1 m^2 (weak edges), no information.
  EXPECT_FALSE(frontend::edge_error_ratio(
      graph, {0, 1, graph::EdgeType::kWeak, at_x(1.0), information(2.0, 1.0)}));
  EXPECT_FALSE(frontend::edge_error_ratio(
      graph, {0, 1, graph::EdgeType::kLoop, at_x(1.0), graph::Information6::Zero()}));
}

}  // namespace
}  // namespace wifislam::slam
