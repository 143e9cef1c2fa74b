// The whole pipeline on frames streamed from the generator (real renders, Kinect-like depth
// noise): loop closure on a small unambiguous loop and determinism. A plain TUM folder through
// the command line is in tum_folder_cli_test.cpp.

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <numbers>

#include <nlohmann/json.hpp>

#include "sim/generate/generator_stream.hpp"
#include "sim/scene/scene_loader.hpp"
#include "slam/frontend/front_end_registry.hpp"
#include "slam/io/run_folder_writer.hpp"
#include "slam/system/slam_system.hpp"
#include "tests/slam/slam_test_scene.hpp"
#include "tests/slam/trajectory_error.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;

struct RunResult {
  std::unique_ptr<slam::system::SlamSystem> system;
  std::map<std::int64_t, Pose> truth;           // frame time (ns) -> camera-to-world
  std::map<std::int64_t, Pose> truth_by_frame;  // frame index -> camera-to-world
};

/// SLAM over the generator's stream, keeping the ground truth aside (SLAM never sees it).
RunResult run_on_generated(const sim::scene::Scene& scene, double fps, std::int64_t max_frames,
                           const slam::SlamOptions& options) {
  sim::generate::GenerateOptions generate;
  generate.fps = fps;
  generate.max_frames = max_frames;
  sim::generate::GeneratorStream stream(scene, generate);
  slam::system::StreamInfo info{stream.intrinsics(), stream.camera_in_base(), stream.has_wifi(),
                                stream.has_odometry()};
  RunResult result;
  result.system = std::make_unique<slam::system::SlamSystem>(options, info);
  while (std::optional<SensorEvent> event = stream.next()) {
    result.system->process(*event);
    if (const auto* frame = std::get_if<RgbdFrame>(&*event)) {
      result.truth[frame->time.ns] = stream.last_frame_ground_truth();
      result.truth_by_frame[frame->index] = stream.last_frame_ground_truth();
    }
  }
  result.system->finish();
  return result;
}

/// Fewer features than the default keep the suite fast; the loop is short and feature-rich.
slam::SlamOptions test_options() {
  slam::SlamOptions options;
  options.features.max_keypoints = 500;
  return options;
}

// A straight 24 m corridor with offices, unique walls: no loop to close, so the end-point error
// is the visual odometry's drift (noise on: Kinect depth noise, quantisation, dropouts).
constexpr const char* kStraightCorridorYaml = R"(version: 1
name: straight_corridor
seed: 11
building: {wall_height_m: 2.8, wall_thickness_m: 0.15}
nodes:
  - {id: A, position_m: [0, 0]}
  - {id: B, position_m: [24, 0]}
corridors:
  - id: c
    from: A
    to: B
    width_m: 2.0
    rooms: [{side: left, from_m: 1.0, to_m: 23.0, room_length_m: 4.4, depth_m: 3.5}]
appearance: {aliasing: 0.0, posters_per_10m: 2.0}
access_points: {placement: rooms, count: 6}
route:
  nodes: [A, B]
  speed_mps: 0.5
  pause: {spacing_m: [3.0, 4.0], duration_s: 2.0}
radio: {environment: office}
)";

TEST(RgbdslamEndToEnd, OdometryOnAStraightCorridorDriftsLessThanTwoPercent) {
  const sim::scene::Scene scene =
      sim::scene::load_scene_yaml(kStraightCorridorYaml, "<straight corridor>");
  const RunResult run = run_on_generated(scene, 5.0, -1, slam::SlamOptions{});
  EXPECT_EQ(run.system->loop_closures().size(), 0u);
  const Trajectory estimate = run.system->trajectory();
  ASSERT_GT(estimate.size(), 300u);
  // Anchor the estimate at the first ground-truth pose (SLAM starts at the identity), then
  // compare the end points: drift, not an alignment over the whole path.
  const Pose anchor = run.truth.at(estimate.front().time.ns) * estimate.front().pose().inverse();
  double path_m = 0.0;
  const Pose* previous = nullptr;
  for (const StampedPose& p : estimate) {
    const Pose& truth = run.truth.at(p.time.ns);
    if (previous) path_m += (truth.translation() - previous->translation()).norm();
    previous = &truth;
  }
  const Pose end = anchor * estimate.back().pose();
  const double drift_m =
      (end.translation() - run.truth.at(estimate.back().time.ns).translation()).norm();
  EXPECT_NEAR(path_m, 24.0, 0.5);
  EXPECT_LT(drift_m, 0.02 * path_m) << "drift " << drift_m << " m over " << path_m << " m";
}

TEST(RgbdslamEndToEnd, ClosesTheLoopOnASmallLowAliasingLoop) {
  const RunResult run = run_on_generated(test::small_loop_scene(), 5.0, -1, test_options());
  const slam::system::SlamSystem& system = *run.system;
  const slam::graph::PoseGraph& graph = system.graph();
  // A closure is correct when its measured relative pose agrees with the truth within eval's
  // thresholds (0.3 m, 5 deg; eval/eval_options.hpp).
  int true_closures = 0;
  for (const slam::system::LoopClosureRecord& l : system.loop_closures()) {
    const Pose& a = run.truth_by_frame.at(graph.node(l.from).frame_index);
    const Pose& b = run.truth_by_frame.at(graph.node(l.to).frame_index);
    const Pose truth_rel = a.inverse() * b;
    if (translation_distance_m(truth_rel, l.from_to) < 0.3 &&
        rotation_angle_rad(truth_rel, l.from_to) < 5.0 * std::numbers::pi / 180.0) {
      ++true_closures;
    }
    std::printf(
        "loop closure %d - %d (%s, %d inliers): %.2f m apart, relative pose error %.3f m "
        "%.2f deg\n",
        l.from, l.to, slam::frontend::to_string(l.role).c_str(), l.inliers,
        translation_distance_m(a, b), translation_distance_m(truth_rel, l.from_to),
        rotation_angle_rad(truth_rel, l.from_to) * 180.0 / std::numbers::pi);
  }
  const test::AlignedError ate = test::aligned_translation_error(system.trajectory(), run.truth);
  std::printf(
      "%lld frames, %zu keyframes, %zu loop closures (%d correct against ground truth), "
      "ATE RMSE %.3f m (max %.3f m), tracking failures %lld\n",
      static_cast<long long>(system.frame_records().size()), graph.node_count(),
      system.loop_closures().size(), true_closures, ate.rmse_m, ate.max_m,
      static_cast<long long>(system.instrumentation().counter(slam::counter::kTrackingFailures)));
  EXPECT_GE(true_closures, 1);
  EXPECT_EQ(static_cast<std::size_t>(true_closures), system.loop_closures().size());
  EXPECT_EQ(ate.pairs, system.frame_records().size());
  // 36 m of route around a 28 m loop: closed and optimised, the trajectory stays within
  // decimetres of the truth (measured: 0.06 m).
  EXPECT_LT(ate.rmse_m, 0.25);
}

TEST(RgbdslamEndToEnd, TwoRunsGiveIdenticalTrajectoriesAndEdges) {
  const sim::scene::Scene scene = test::small_loop_scene();
  const RunResult a = run_on_generated(scene, 5.0, 80, test_options());
  const RunResult b = run_on_generated(scene, 5.0, 80, test_options());
  const Trajectory ta = a.system->trajectory(), tb = b.system->trajectory();
  ASSERT_EQ(ta.size(), tb.size());
  for (std::size_t i = 0; i < ta.size(); ++i) {
    EXPECT_EQ(format_tum_line(ta[i]), format_tum_line(tb[i])) << i;
  }
  EXPECT_EQ(slam::io::graph_to_json(a.system->graph()).dump(),
            slam::io::graph_to_json(b.system->graph()).dump());
  EXPECT_GT(a.system->graph().node_count(), 3u);
}

// RGBDSLAMv2's `optimizer_skip_step`: besides after loop closures, the graph is optimised after
// every n-th keyframe. On a straight corridor (no loop to close) the only other optimisations are
// the ones at the end of the run, so the count is exactly (keyframes - 1) / n more than without.
TEST(RgbdslamEndToEnd, OptimizerSkipStepOptimisesAfterEveryNthKeyframe) {
  const sim::scene::Scene scene =
      sim::scene::load_scene_yaml(kStraightCorridorYaml, "<straight corridor>");
  std::map<int, std::pair<std::int64_t, std::size_t>> optimisations_and_keyframes;
  for (int step : {0, 1, 3}) {
    slam::SlamOptions options = test_options();
    options.rgbdslam.optimizer_skip_step = step;
    const RunResult run = run_on_generated(scene, 5.0, 60, options);
    EXPECT_EQ(run.system->loop_closures().size(), 0u);
    optimisations_and_keyframes[step] = {
        run.system->instrumentation().counter(slam::counter::kOptimisations),
        run.system->graph().node_count()};
  }
  const std::int64_t at_end = optimisations_and_keyframes.at(0).first;
  EXPECT_GE(at_end, 1);  // the final optimisation
  for (int step : {1, 3}) {
    const auto [optimisations, keyframes] = optimisations_and_keyframes.at(step);
    ASSERT_GT(keyframes, 6u);
    // Keyframes 1 .. K-1 (a graph of one node has nothing to optimise).
    EXPECT_EQ(optimisations, at_end + static_cast<std::int64_t>(keyframes - 1) / step) << step;
  }
}

/// A front end unlike RGBD-SLAM, defined outside the library: the last keyframe plus every
/// qualifying keyframe of the similar Wi-Fi clusters, only the best loop hypothesis accepted.
class WifiOnlyFrontEnd final : public slam::frontend::FrontEnd {
 public:
  WifiOnlyFrontEnd()
      : FrontEnd("wifi_only_test", std::make_unique<slam::frontend::AcceptBestLoopHypothesis>()) {}
  std::vector<slam::frontend::Candidate> select(
      const slam::frontend::SelectionQuery& query) override {
    std::vector<slam::frontend::Candidate> out;
    if (query.keyframe >= 2)
      out.push_back({query.keyframe - 2, slam::frontend::CandidateRole::kPredecessor});
    std::vector<slam::graph::KeyframeId> qualifying;
    for (slam::graph::KeyframeId k = 0; k < query.keyframe; ++k) {
      if (query.loop_rule->is_loop(k, query.keyframe)) qualifying.push_back(k);
    }
    for (slam::graph::KeyframeId k : wifi()->bound(qualifying)) {
      out.push_back({k, slam::frontend::CandidateRole::kLongTerm});
    }
    return out;
  }
};

// --wifi works with any registered front end through the real pipeline: the module clusters the
// keyframes, and the per-role counters add up to the pipeline's totals.
TEST(RgbdslamEndToEnd, AnotherFrontEndRunsWithTheWifiModule) {
  slam::frontend::register_front_end("wifi_only_test", [](const slam::frontend::FrontEndContext&) {
    return std::make_unique<WifiOnlyFrontEnd>();
  });
  slam::SlamOptions options = test_options();
  options.frontend = "wifi_only_test";
  options.wifi.enabled = true;
  const RunResult run = run_on_generated(test::small_loop_with_wifi_scene(), 3.0, 200, options);
  const slam::system::SlamSystem& system = *run.system;
  ASSERT_NE(system.front_end().wifi(), nullptr);
  EXPECT_GT(system.front_end().wifi()->pause_count(), 3);
  const slam::wifi::WifiClusterMap& clusters = system.front_end().wifi()->clusters();
  EXPECT_GE(clusters.clusters().size(), 2u);
  std::size_t clustered = 0;
  for (const slam::wifi::WifiCluster& c : clusters.clusters()) clustered += c.keyframes.size();
  EXPECT_GT(clustered, system.graph().node_count() / 2);

  const slam::util::Instrumentation& inst = system.instrumentation();
  std::int64_t candidate_comparisons = 0, accepted = 0;
  for (const auto& [role, work] : inst.roles()) {
    EXPECT_LE(work.accepted, work.verified) << role;
    EXPECT_LE(work.verified, work.comparisons) << role;
    if (role == slam::frontend::kTrackingRole) continue;
    candidate_comparisons += work.comparisons;
    accepted += work.accepted;
  }
  EXPECT_EQ(candidate_comparisons, inst.counter(slam::counter::kCandidateComparisons));
  EXPECT_GT(inst.roles().at(slam::frontend::kTrackingRole).comparisons, 0);
  // Accepted candidate comparisons are the graph's visual and loop edges, less tracking's.
  std::int64_t visual_or_loop = 0;
  for (const slam::graph::GraphEdge& e : system.graph().edges()) {
    if (e.type == slam::graph::EdgeType::kVisual || e.type == slam::graph::EdgeType::kLoop)
      ++visual_or_loop;
  }
  EXPECT_LE(accepted, visual_or_loop);
  EXPECT_EQ(accepted + inst.counter(slam::counter::kRejectedHypotheses), [&] {
    std::int64_t verified = 0;
    for (const auto& [role, work] : inst.roles()) {
      if (role != slam::frontend::kTrackingRole) verified += work.verified;
    }
    return verified;
  }());
}

}  // namespace
}  // namespace wifislam
