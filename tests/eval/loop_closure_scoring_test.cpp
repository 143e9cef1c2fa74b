// Loop closures scored against exact ground truth on a hand-built aliasing_ladder run (real
// OSMesa depth renders of the generated world): a true closure, a false one between two
// identical-looking wings, a closure with a wrong relative pose, and a missed revisit.
#include <filesystem>
#include <numbers>

#include <unistd.h>

#include <gtest/gtest.h>

#include "eval/evaluate_run.hpp"
#include "tests/eval/ladder_dataset.hpp"

namespace wifislam::eval {
namespace {

namespace fs = std::filesystem;
using test::LadderRun;
using test::LoopClosureRow;

fs::path scratch(const std::string& name) {
  return fs::temp_directory_path() / ("wifislam_eval_" + name + "_" + std::to_string(::getpid()));
}

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
  static void TearDownTestSuite() {
    fs::remove_all(scratch("ladder"));
    delete run_;
  }
  static LadderRun* run_;
};
LadderRun* LadderScoring::run_ = nullptr;

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
    EXPECT_TRUE(c.correct) << c.verdict;
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
  // away. False positive, and the revisit stays missed.
  {
    const Pose looks_like = run.true_relative(a, a);
    test::write_loop_closures(run, {{a, aliased, nudged(looks_like)}});
    const RunEvaluation ev = evaluate_run(run.run_dir, run.dataset_dir, options);
    ASSERT_EQ(ev.loop_closures_detected, 1);
    const ScoredLoopClosure& c = ev.loop_closure_score.closures[0];
    EXPECT_FALSE(c.correct);
    EXPECT_NEAR(c.overlap.distance_m, 20.0, 0.1);
    EXPECT_EQ(ev.false_positives, 1);
    EXPECT_DOUBLE_EQ(ev.false_positive_pct, 100.0);
    EXPECT_EQ(ev.false_negatives, 1);

    // Without the geometric bound the depth test alone rejects it.
    EvalOptions unbounded = options;
    unbounded.overlap_max_distance_m = 100.0;
    const RunEvaluation ev2 = evaluate_run(run.run_dir, run.dataset_dir, unbounded);
    const ScoredLoopClosure& c2 = ev2.loop_closure_score.closures[0];
    EXPECT_FALSE(c2.correct);
    EXPECT_TRUE(c2.overlap.depth_checked);
    EXPECT_LT(c2.overlap.fraction, 0.05);
    EXPECT_EQ(c2.verdict, "views do not overlap (depth)");
  }

  // The right place with a wrong relative pose (1 m off): false positive.
  {
    Pose off = run.true_relative(a, revisit);
    off.translation() += Eigen::Vector3d(1.0, 0, 0);
    test::write_loop_closures(run, {{a, revisit, off}});
    const RunEvaluation ev = evaluate_run(run.run_dir, run.dataset_dir, options);
    const ScoredLoopClosure& c = ev.loop_closure_score.closures[0];
    EXPECT_FALSE(c.correct);
    EXPECT_TRUE(c.overlap.overlap);
    EXPECT_EQ(c.verdict, "relative pose off");
    EXPECT_NEAR(c.translation_error_m, 1.0, 1e-6);
    EXPECT_EQ(ev.false_positives, 1);
    EXPECT_EQ(ev.false_negatives, 1);
  }
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
  EXPECT_TRUE(ev.loop_closure_score.closures[0].correct);
  // The exact relative pose does not rescue a pair that does not see the same place.
  EXPECT_LT(ev.loop_closure_score.closures[1].overlap.fraction, 0.05);
  EXPECT_FALSE(ev.loop_closure_score.closures[1].correct);
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
  EXPECT_TRUE(ev.loop_closure_score.closures[0].correct);
  EXPECT_FALSE(ev.loop_closure_score.closures[0].overlap.depth_checked);
  EXPECT_FALSE(ev.loop_closure_score.closures[1].correct);
  EXPECT_EQ(ev.revisit_episodes, 1);
  EXPECT_EQ(ev.false_negatives, 0);
  fs::remove_all(root);
}

}  // namespace
}  // namespace wifislam::eval
