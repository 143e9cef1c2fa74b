// Loop closures scored against exact ground truth on a hand-built aliasing_ladder run (real
// OSMesa depth renders of the generated world): a true closure, a false one between two
// identical-looking wings, closures with a wrong relative pose at the right place, a missed
// revisit; graph.json edges of either type, pruned or not.
#include <filesystem>
#include <fstream>
#include <numbers>

#include <unistd.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "eval/evaluate_run.hpp"
#include "tests/eval/ladder_dataset.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::eval {
namespace {

namespace fs = std::filesystem;
using test::LadderRun;
using test::LoopClosureRow;

fs::path scratch(const std::string& name) { return test::scratch_folder(name); }

/// A small error, well inside the tolerance: what a good RANSAC estimate looks like.
Pose nudged(const Pose& p) {
  Pose n = Pose::Identity();
  n.linear() =
      Eigen::AngleAxisd(0.5 * std::numbers::pi / 180, Eigen::Vector3d::UnitY()).toRotationMatrix();
  n.translation() = Eigen::Vector3d(0.02, 0.0, -0.02);
  return p * n;
}

class LadderScoring : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    run_ = new LadderRun(test::build_ladder_run(scratch("ladder"), true));
  }
  static void TearDownTestSuite() { delete run_; }
  // Every test starts from a run without graph.json and without loop closures.
  void SetUp() override {
    fs::remove(run_->run_dir / "graph.json");
    test::write_loop_closures(*run_, {});
  }
  static LadderRun* run_;
};
LadderRun* LadderScoring::run_ = nullptr;

/// A transit keyframe near (x, y) (the camera passes every point of the ladder at most once).
int transit_keyframe_near(const LadderRun& run, double x_m, double y_m) {
  int best = -1;
  double best_d = 1e9;
  for (std::size_t k = 0; k < run.keyframe_poses.size(); ++k) {
    if (run.keyframe_segment[k] != "transit") continue;
    const double d =
        (run.keyframe_poses[k].translation().head<2>() - Eigen::Vector2d(x_m, y_m)).norm();
    if (d < best_d) best_d = d, best = static_cast<int>(k);
  }
  return best;
}

/// `p` moved by `translation_m` along x and turned by `angle_deg` about y (camera frame).
Pose perturbed(const Pose& p, double translation_m, double angle_deg) {
  Pose n = Pose::Identity();
  n.linear() = Eigen::AngleAxisd(angle_deg * std::numbers::pi / 180, Eigen::Vector3d::UnitY())
                   .toRotationMatrix();
  n.translation() = Eigen::Vector3d(translation_m, 0.0, 0.0);
  return p * n;
}

TEST_F(LadderScoring, TrueClosureFalseAliasedClosurePoseErrorAndMissedRevisit) {
  const LadderRun& run = *run_;
  const int a = run.keyframe_near("A", 4.5);
  const int revisit = run.keyframe_near("revisit", 4.8);
  const int aliased = run.keyframe_near("aliased", 4.5);
  ASSERT_GE(a, 0);
  ASSERT_GT(revisit, a);
  ASSERT_GT(aliased, a);
  ASSERT_LT(aliased, revisit);
  const EvalOptions options;

  // No closure at all: the revisit of wing 0 is one episode, missed.
  {
    const RunEvaluation ev = evaluate_run(run.run_dir, run.dataset_dir, options);
    EXPECT_LT(ev.ate_rmse_m, 1e-6);  // the estimate is the ground truth moved rigidly
    EXPECT_EQ(ev.loop_closures_detected, 0);
    EXPECT_DOUBLE_EQ(ev.false_positive_pct, 0.0);
    ASSERT_EQ(ev.revisit_episodes, 1);
    EXPECT_EQ(ev.false_negatives, 1);
    EXPECT_DOUBLE_EQ(ev.false_negative_pct, 100.0);
    EXPECT_TRUE(ev.overlap_used_depth);
    const RevisitEpisode& e = ev.loop_closure_score.episodes[0];
    // The episode is the revisit leg (the aliased wing, 20 m away, is no revisit).
    EXPECT_EQ(run.keyframe_segment[static_cast<std::size_t>(e.first_keyframe)], "revisit");
    EXPECT_EQ(run.keyframe_segment[static_cast<std::size_t>(e.last_keyframe)], "revisit");
    EXPECT_EQ(run.keyframe_segment[static_cast<std::size_t>(e.first_partner)], "A");
    EXPECT_GE(e.first_partner_path_m, options.revisit_min_path_m);
    EXPECT_GE(e.revisiting_keyframes, 6);
    EXPECT_EQ(ev.keyframes, static_cast<std::int64_t>(run.keyframe_poses.size()));
    EXPECT_DOUBLE_EQ(ev.loop_closure_detection_s, 1.5);
    EXPECT_EQ(ev.candidate_comparisons, 120);
  }

  // A true closure: correct, and it covers the episode.
  {
    test::write_loop_closures(run, {{a, revisit, nudged(run.true_relative(a, revisit))}});
    const RunEvaluation ev = evaluate_run(run.run_dir, run.dataset_dir, options);
    ASSERT_EQ(ev.loop_closures_detected, 1);
    const ScoredLoopClosure& c = ev.loop_closure_score.closures[0];
    EXPECT_TRUE(c.correct()) << to_string(c.verdict);
    EXPECT_TRUE(c.overlap.depth_checked);
    EXPECT_GT(c.overlap.fraction, 0.5);
    EXPECT_NEAR(c.translation_error_m, std::sqrt(2) * 0.02, 1e-6);
    EXPECT_NEAR(c.rotation_error_deg, 0.5, 1e-6);
    EXPECT_EQ(ev.false_positives, 0);
    EXPECT_EQ(ev.false_negatives, 0);
    EXPECT_DOUBLE_EQ(ev.false_negative_pct, 0.0);
    EXPECT_EQ(c.episode, 0);
  }

  // The aliased wing: visually the same place (estimated relative pose ~ identity), truly 20 m
  // away. Wrong place, far, and the revisit stays missed.
  {
    const Pose looks_like = run.true_relative(a, a);
    test::write_loop_closures(run, {{a, aliased, nudged(looks_like)}});
    const RunEvaluation ev = evaluate_run(run.run_dir, run.dataset_dir, options);
    ASSERT_EQ(ev.loop_closures_detected, 1);
    const ScoredLoopClosure& c = ev.loop_closure_score.closures[0];
    EXPECT_EQ(c.verdict, LoopClosureVerdict::kWrongPlace);
    EXPECT_TRUE(c.far);
    EXPECT_NEAR(c.true_distance_m, 20.0, 0.1);
    EXPECT_NEAR(c.overlap.distance_m, 20.0, 0.1);
    EXPECT_EQ(ev.false_positives, 1);
    EXPECT_DOUBLE_EQ(ev.false_positive_pct, 100.0);
    EXPECT_EQ(ev.loop_closure_score.online.far_wrong_place, 1);
    EXPECT_EQ(ev.false_negatives, 1);

    // Without the geometric bound the depth test sees no overlap either (reported, not the
    // verdict).
    EvalOptions unbounded = options;
    unbounded.overlap_max_distance_m = 100.0;
    const RunEvaluation ev2 = evaluate_run(run.run_dir, run.dataset_dir, unbounded);
    const ScoredLoopClosure& c2 = ev2.loop_closure_score.closures[0];
    EXPECT_EQ(c2.verdict, LoopClosureVerdict::kWrongPlace);
    EXPECT_TRUE(c2.overlap.depth_checked);
    EXPECT_LT(c2.overlap.fraction, 0.05);
  }

  // The right place with a relative pose 0.6 m off: right place, imprecise; not a false
  // positive, not a detection either.
  {
    Pose off = run.true_relative(a, revisit);
    off.translation() += Eigen::Vector3d(0.6, 0, 0);
    test::write_loop_closures(run, {{a, revisit, off}});
    const RunEvaluation ev = evaluate_run(run.run_dir, run.dataset_dir, options);
    const ScoredLoopClosure& c = ev.loop_closure_score.closures[0];
    EXPECT_EQ(c.verdict, LoopClosureVerdict::kRightPlaceImprecise);
    EXPECT_TRUE(c.overlap.overlap);
    EXPECT_NEAR(c.translation_error_m, 0.6, 1e-6);
    EXPECT_LT(c.true_distance_m, 1.0);
    EXPECT_EQ(ev.loop_closure_score.online.right_place_imprecise, 1);
    EXPECT_EQ(ev.false_positives, 0);
    EXPECT_EQ(ev.false_negatives, 1);
  }

  // The right place with a relative pose 2 m off: wrong place (the map would be torn), not far.
  {
    Pose off = run.true_relative(a, revisit);
    off.translation() += Eigen::Vector3d(2.0, 0, 0);
    test::write_loop_closures(run, {{a, revisit, off}});
    const RunEvaluation ev = evaluate_run(run.run_dir, run.dataset_dir, options);
    const ScoredLoopClosure& c = ev.loop_closure_score.closures[0];
    EXPECT_EQ(c.verdict, LoopClosureVerdict::kWrongPlace);
    EXPECT_FALSE(c.far);
    EXPECT_EQ(ev.false_positives, 1);
    EXPECT_EQ(ev.loop_closure_score.online.far_wrong_place, 0);
    EXPECT_EQ(ev.false_negatives, 1);
  }
}

// An external system's closure stamps can fall on one keyframe pair twice: without graph.json,
// a row naming an earlier row's pair (in either order) is that closure again, scored once.
TEST_F(LadderScoring, CsvRowsRepeatingAKeyframePairAreScoredOnceAndCounted) {
  const LadderRun& run = *run_;
  const int a = run.keyframe_near("A", 4.5);
  const int revisit = run.keyframe_near("revisit", 4.8);
  const int aliased = run.keyframe_near("aliased", 4.5);
  const Pose looks_like = nudged(run.true_relative(a, a));
  test::write_loop_closures(run, {{a, aliased, looks_like},
                                  {a, revisit, nudged(run.true_relative(a, revisit))},
                                  {aliased, a, looks_like.inverse()},
                                  {a, aliased, looks_like}});
  const RunEvaluation ev = evaluate_run(run.run_dir, run.dataset_dir, EvalOptions());
  EXPECT_EQ(ev.loop_closure_csv_rows, 4);
  EXPECT_EQ(ev.loop_closure_csv_repeated_rows, 2);
  ASSERT_EQ(ev.loop_closure_score.closures.size(), 2u);
  // The first row of each pair is the one scored, in input order.
  EXPECT_EQ(ev.loop_closure_score.closures[0].edge.where,
            (run.run_dir / "loop_closures.csv").string() + ":2");
  EXPECT_EQ(ev.loop_closure_score.closures[1].edge.to_keyframe, revisit);
  EXPECT_EQ(ev.false_positives, 1);
  EXPECT_DOUBLE_EQ(ev.false_positive_pct, 50.0);
  const nlohmann::ordered_json j = ev.to_ordered_json();
  EXPECT_EQ(j["loop_closures"]["loop_closure_csv_repeated_rows"], 2);
  EXPECT_FALSE(ev.flat_metrics().contains("loop_closure_csv_repeated_rows"));

  // With graph.json the graph's edges are scored and the count is not reported.
  test::write_graph(run, {{a, revisit, "loop", nudged(run.true_relative(a, revisit)), 0}});
  const RunEvaluation from_graph = evaluate_run(run.run_dir, run.dataset_dir, EvalOptions());
  EXPECT_EQ(from_graph.loop_closure_score.closures.size(), 1u);
  EXPECT_FALSE(
      from_graph.to_ordered_json()["loop_closures"].contains("loop_closure_csv_repeated_rows"));
}

TEST_F(LadderScoring, DepthOverlapOfRevisitVersusAliasedWing) {
  const LadderRun& run = *run_;
  // Same place, same heading: nearly everything lands. Identical-looking wing 20 m east: nothing.
  EvalOptions unbounded;
  unbounded.overlap_max_distance_m = 1000;
  const int a = run.keyframe_near("A", 6.5);
  const int revisit = run.keyframe_near("revisit", 6.8);
  const int aliased = run.keyframe_near("aliased", 6.5);
  test::write_loop_closures(run, {{a, revisit, run.true_relative(a, revisit)},
                                  {a, aliased, run.true_relative(a, aliased)}});
  const RunEvaluation ev = evaluate_run(run.run_dir, run.dataset_dir, unbounded);
  ASSERT_EQ(ev.loop_closure_score.closures.size(), 2u);
  EXPECT_GT(ev.loop_closure_score.closures[0].overlap.fraction, 0.6);
  EXPECT_TRUE(ev.loop_closure_score.closures[0].correct());
  // The views do not overlap, but the estimated relative pose is the true one: the pose decides,
  // so the edge is correct (it pulls the map the right way).
  EXPECT_LT(ev.loop_closure_score.closures[1].overlap.fraction, 0.05);
  EXPECT_TRUE(ev.loop_closure_score.closures[1].correct());
}

// graph.json: every visual or loop edge 10 m of path apart is scored by its pose, whatever its
// type; online and after pruning are two sets.
TEST_F(LadderScoring, GraphEdgesScoredByPoseOnlineAndAfterPruning) {
  const LadderRun& run = *run_;
  const int a = run.keyframe_near("A", 4.5);
  const int a2 = run.keyframe_near("A", 6.5);
  const int revisit = run.keyframe_near("revisit", 4.8);
  const int revisit2 = run.keyframe_near("revisit", 6.8);
  const int aliased = run.keyframe_near("aliased", 4.5);
  const int east = transit_keyframe_near(run, 10.0, 6.0);  // east wing, facing south
  ASSERT_GE(east, 0);
  ASSERT_GT(aliased, east);
  const EvalOptions options;
  test::write_graph(
      run, {
               // correct (and it covers the revisit episode)
               {a, revisit, "loop", nudged(run.true_relative(a, revisit)), 1},
               // a "visual" edge to the identical-looking wing 20 m away: wrong place, far
               {a, aliased, "visual", nudged(run.true_relative(a, a)), 1},
               // 0.12 m / 1.8 deg from the truth between views that do not overlap: correct
               {a, east, "loop", perturbed(run.true_relative(a, east), 0.12, 1.8), 0},
               // right place, 0.6 m off: imprecise
               {a2, revisit2, "loop", perturbed(run.true_relative(a2, revisit2), 0.6, 0), -1},
               // a local visual edge (under 10 m of path): not scored
               {revisit - 2, revisit, "visual", run.true_relative(revisit - 2, revisit), 0},
           });
  // loop_closures.csv knows the role of one loop edge.
  test::write_loop_closures(run, {{a, revisit, nudged(run.true_relative(a, revisit))}});

  const RunEvaluation ev = evaluate_run(run.run_dir, run.dataset_dir, options);
  const LoopClosureScore& s = ev.loop_closure_score;
  EXPECT_EQ(ev.loop_closure_source, "graph.json");
  ASSERT_EQ(s.closures.size(), 4u);
  EXPECT_EQ(s.edges_considered, 5);
  EXPECT_EQ(s.edges_short_path, 1);
  EXPECT_EQ(s.closures[0].verdict, LoopClosureVerdict::kCorrect);
  EXPECT_EQ(s.closures[0].edge.role, "sampled");
  EXPECT_EQ(s.closures[1].verdict, LoopClosureVerdict::kWrongPlace);
  EXPECT_EQ(s.closures[1].edge.type, "visual");
  EXPECT_EQ(s.closures[1].edge.role, "");
  EXPECT_TRUE(s.closures[1].far);
  EXPECT_GE(s.closures[1].path_between_m, options.revisit_min_path_m);
  EXPECT_EQ(s.closures[2].verdict, LoopClosureVerdict::kCorrect);
  EXPECT_FALSE(s.closures[2].overlap.overlap);
  EXPECT_NEAR(s.closures[2].translation_error_m, 0.12, 1e-6);
  EXPECT_NEAR(s.closures[2].rotation_error_deg, 1.8, 1e-6);
  EXPECT_EQ(s.closures[3].verdict, LoopClosureVerdict::kRightPlaceImprecise);
  EXPECT_FALSE(s.closures[3].edge.pruned);  // no "pruned" key: kept

  // Online: all four.
  EXPECT_EQ(s.online.scored, 4);
  EXPECT_EQ(s.online.correct, 2);
  EXPECT_EQ(s.online.right_place_imprecise, 1);
  EXPECT_EQ(s.online.wrong_place, 1);
  EXPECT_EQ(s.online.far_wrong_place, 1);
  EXPECT_DOUBLE_EQ(s.online.false_positive_pct, 25.0);
  ASSERT_EQ(s.episodes.size(), 1u);
  EXPECT_EQ(s.online.false_negatives, 0);
  // After pruning: the true closure and the false one are gone, the revisit is missed.
  EXPECT_EQ(s.after_pruning.scored, 2);
  EXPECT_EQ(s.after_pruning.correct, 1);
  EXPECT_EQ(s.after_pruning.right_place_imprecise, 1);
  EXPECT_EQ(s.after_pruning.wrong_place, 0);
  EXPECT_EQ(s.after_pruning.far_wrong_place, 0);
  EXPECT_DOUBLE_EQ(s.after_pruning.false_positive_pct, 0.0);
  EXPECT_EQ(s.after_pruning.false_negatives, 1);
  EXPECT_TRUE(s.episodes[0].detected_online);
  EXPECT_FALSE(s.episodes[0].detected_after_pruning);
  // The paper's numbers are the online set.
  EXPECT_EQ(ev.false_positives, 1);
  EXPECT_EQ(ev.loop_closures_detected, 4);

  const nlohmann::ordered_json flat = ev.flat_metrics();
  EXPECT_EQ(flat["online_wrong_place"], 1);
  EXPECT_EQ(flat["pruned_wrong_place"], 0);
  EXPECT_EQ(flat["online_far_wrong_place"], 1);
  EXPECT_EQ(flat["pruned_false_negatives"], 1);
  const nlohmann::ordered_json j = ev.to_ordered_json();
  EXPECT_EQ(j["loop_closures"]["closures"][1]["verdict"], "wrong_place");
  EXPECT_EQ(j["loop_closures"]["closures"][1]["pruned"], true);
  EXPECT_EQ(j["loop_closures"]["pruned"]["scored"], 2);
}

TEST_F(LadderScoring, MalformedGraphEdgeIsLocated) {
  const LadderRun& run = *run_;
  test::write_graph(run, {});
  std::ifstream in(run.run_dir / "graph.json");
  nlohmann::json g = nlohmann::json::parse(in);
  g["edges"][3]["from_to"]["q_xyzw"] = {0, 0, 1};
  std::ofstream(run.run_dir / "graph.json") << g.dump();
  try {
    evaluate_run(run.run_dir, run.dataset_dir, EvalOptions{});
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("graph.json"), std::string::npos) << e.what();
    EXPECT_EQ(e.key_path(), "edges[3].from_to.q_xyzw");
  }
  g["edges"][3]["from_to"]["q_xyzw"] = {0, 0, 0, 1};
  g["edges"][3]["to"] = 100000;
  std::ofstream(run.run_dir / "graph.json") << g.dump();
  try {
    evaluate_run(run.run_dir, run.dataset_dir, EvalOptions{});
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.key_path(), "edges[3].to");
    EXPECT_NE(e.detail().find("keyframes.txt"), std::string::npos) << e.what();
  }
}

TEST(LoopClosureVerdict, ThresholdsDecideInOrder) {
  const EvalOptions o;
  EXPECT_EQ(classify_loop_closure(0.3, 5.0, 50.0, o), LoopClosureVerdict::kCorrect);
  EXPECT_EQ(classify_loop_closure(0.31, 1.0, 2.9, o), LoopClosureVerdict::kRightPlaceImprecise);
  EXPECT_EQ(classify_loop_closure(0.1, 9.9, 1.0, o), LoopClosureVerdict::kRightPlaceImprecise);
  EXPECT_EQ(classify_loop_closure(0.31, 1.0, 3.1, o), LoopClosureVerdict::kWrongPlace);
  EXPECT_EQ(classify_loop_closure(1.1, 1.0, 0.5, o), LoopClosureVerdict::kWrongPlace);
  EXPECT_EQ(classify_loop_closure(0.5, 10.5, 0.5, o), LoopClosureVerdict::kWrongPlace);
  EXPECT_FALSE(is_far_wrong_place(LoopClosureVerdict::kWrongPlace, 12.0, o));
  EXPECT_TRUE(is_far_wrong_place(LoopClosureVerdict::kWrongPlace, 12.1, o));
  EXPECT_FALSE(is_far_wrong_place(LoopClosureVerdict::kCorrect, 40.0, o));
}

TEST(LadderScoringWithoutDepth, FallsBackToGeometricBoundAndSaysSo) {
  const fs::path root = scratch("ladder_nodepth");
  const LadderRun run = test::build_ladder_run(root, false);
  const int a = run.keyframe_near("A", 4.5);
  const int revisit = run.keyframe_near("revisit", 4.8);
  const int aliased = run.keyframe_near("aliased", 4.5);
  test::write_loop_closures(
      run, {{a, revisit, run.true_relative(a, revisit)}, {a, aliased, run.true_relative(a, a)}});
  const RunEvaluation ev = evaluate_run(run.run_dir, run.dataset_dir, EvalOptions{});
  EXPECT_FALSE(ev.overlap_used_depth);
  EXPECT_NE(ev.overlap_method.find("geometric bound only"), std::string::npos);
  ASSERT_EQ(ev.loop_closures_detected, 2);
  EXPECT_TRUE(ev.loop_closure_score.closures[0].correct());
  EXPECT_FALSE(ev.loop_closure_score.closures[0].overlap.depth_checked);
  EXPECT_FALSE(ev.loop_closure_score.closures[1].correct());
  EXPECT_EQ(ev.revisit_episodes, 1);
  EXPECT_EQ(ev.false_negatives, 0);
  fs::remove_all(root);
}

}  // namespace
}  // namespace wifislam::eval
