// Association, Umeyama alignment, ATE and RPE on trajectories with known answers.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "eval/alignment.hpp"
#include "eval/association.hpp"
#include "eval/trajectory_error.hpp"

namespace wifislam::eval {
namespace {

Pose known_transform() {
  Pose t = Pose::Identity();
  t.linear() = (Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(-0.3, Eigen::Vector3d(1, 2, 0.5).normalized()))
                   .toRotationMatrix();
  t.translation() = Eigen::Vector3d(12.5, -3.25, 0.8);
  return t;
}

/// A wandering planar path with headings, camera 1 m above the floor.
std::vector<Pose> planar_path(int n, std::uint64_t seed) {
  Rng rng = Rng::stream(seed, "eval_test/path");
  std::vector<Pose> poses;
  double x = 0, y = 0, yaw = 0;
  for (int i = 0; i < n; ++i) {
    yaw += rng.uniform(-0.08, 0.08);
    x += 0.05 * std::cos(yaw);
    y += 0.05 * std::sin(yaw);
    poses.push_back(camera_pose_from_planar(x, y, yaw, 1.0));
  }
  return poses;
}

TEST(Alignment, RecoversKnownRigidTransformExactly) {
  Rng rng = Rng::stream(3, "eval_test/points");
  Eigen::Matrix3Xd source(3, 50);
  for (int i = 0; i < 50; ++i) {
    source.col(i) = Eigen::Vector3d(rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(0, 3));
  }
  const Pose t = known_transform();
  const Eigen::Matrix3Xd target = (t.linear() * source).colwise() + t.translation();
  const Alignment a = align_points(source, target, false);
  EXPECT_LT((a.rotation - t.linear()).norm(), 1e-9);
  EXPECT_LT((a.translation_m - t.translation()).norm(), 1e-9);
  EXPECT_DOUBLE_EQ(a.scale, 1.0);
  EXPECT_NEAR(a.rotation.determinant(), 1.0, 1e-12);
}

TEST(Alignment, WithScaleRecoversScale) {
  Rng rng = Rng::stream(4, "eval_test/points");
  Eigen::Matrix3Xd source(3, 40);
  for (int i = 0; i < 40; ++i) {
    source.col(i) = Eigen::Vector3d(rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-1, 1));
  }
  const Pose t = known_transform();
  const double s = 2.75;
  const Eigen::Matrix3Xd target = (s * (t.linear() * source)).colwise() + t.translation();
  const Alignment a = align_points(source, target, true);
  EXPECT_NEAR(a.scale, s, 1e-9);
  EXPECT_LT((a.rotation - t.linear()).norm(), 1e-9);
  EXPECT_LT((a.translation_m - t.translation()).norm(), 1e-9);
  // Rigid alignment of the same points cannot explain the scale: large residual.
  const Alignment rigid = align_points(source, target, false);
  EXPECT_DOUBLE_EQ(rigid.scale, 1.0);
}

TEST(Alignment, RejectsTooFewPoints) {
  Eigen::Matrix3Xd two(3, 2);
  two.setRandom();
  EXPECT_THROW(align_points(two, two, false), InvalidInputError);
}

// Positions that all coincide (an estimate standing still) have no scale: sim3 gave NaN errors
// and said nothing. It says why now; se3 aligns them as before.
TEST(Alignment, SimilarityOfPositionsThatCoincideIsRefusedNamingTheCause) {
  Eigen::Matrix3Xd still(3, 5);
  still.colwise() = Eigen::Vector3d(1.0, 2.0, 0.5);
  Eigen::Matrix3Xd target = still;
  target.row(0).array() += 0.25;
  try {
    align_points(still, target, true);
    ADD_FAILURE() << "sim3 of coinciding positions was accepted";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("no scale"), std::string::npos) << e.what();
  }
  const Alignment rigid = align_points(still, target, false);
  EXPECT_TRUE(rigid.translation_m.allFinite());
  EXPECT_DOUBLE_EQ(rigid.scale, 1.0);
}

TEST(AbsoluteTrajectoryError, FixedOffsetsOfKnownNormGiveThatRmse) {
  // Each ground-truth pose appears twice (a stop of two frames), the estimate is displaced by
  // +d then -d along z and then moved by a known rigid transform. The offsets are uncorrelated
  // with the positions, so the best alignment is the inverse transform and every error is d.
  const double d = 0.125;
  std::vector<Pose> gt, est;
  const Pose t = known_transform();
  for (const Pose& p : planar_path(300, 5)) {
    for (double sign : {1.0, -1.0}) {
      gt.push_back(p);
      Pose e = p;
      e.translation().z() += sign * d;
      est.push_back(t * e);
    }
  }
  const AbsoluteTrajectoryError ate = absolute_trajectory_error(est, gt, false);
  EXPECT_NEAR(ate.rmse_m, d, 1e-9);
  EXPECT_NEAR(ate.mean_m, d, 1e-9);
  EXPECT_NEAR(ate.median_m, d, 1e-9);
  EXPECT_NEAR(ate.max_m, d, 1e-9);
  EXPECT_LT((ate.alignment.rotation - t.linear().transpose()).norm(), 1e-9);
}

TEST(AbsoluteTrajectoryError, GaussianNoiseMatchesExpectedRmse) {
  // Isotropic noise sigma per axis: E|e|^2 = 3 sigma^2. 4000 poses: relative spread of the
  // sample RMSE ~ 1 / sqrt(2 * 3 * 4000) ~ 0.6 %; 3 % tolerance.
  const double sigma = 0.03;
  Rng rng = Rng::stream(6, "eval_test/noise");
  std::vector<Pose> gt = planar_path(4000, 6), est;
  const Pose t = known_transform();
  for (const Pose& p : gt) {
    Pose e = p;
    e.translation() +=
        Eigen::Vector3d(rng.normal(0, sigma), rng.normal(0, sigma), rng.normal(0, sigma));
    est.push_back(t * e);
  }
  const AbsoluteTrajectoryError ate = absolute_trajectory_error(est, gt, false);
  EXPECT_NEAR(ate.rmse_m, std::sqrt(3.0) * sigma, 0.03 * std::sqrt(3.0) * sigma);
}

TEST(RelativePoseError, RigidlyMovedEstimateHasNoDrift) {
  const std::vector<Pose> gt = planar_path(600, 7);
  std::vector<Pose> est;
  for (const Pose& p : gt) est.push_back(known_transform() * p);
  const RelativePoseError rpe = relative_pose_error(est, gt, 1.0);
  EXPECT_GT(rpe.pairs, 500u);
  EXPECT_LT(rpe.translation_per_m, 1e-9);
  EXPECT_LT(rpe.rotation_deg_per_m, 1e-7);
}

TEST(RelativePoseError, HeadingDriftPerMetreIsRecovered) {
  // The estimate turns k deg about the origin per metre travelled: the rotation error of a
  // segment is exactly k x its length.
  const double k_deg = 0.8;
  const std::vector<Pose> gt = planar_path(800, 8);
  const std::vector<double> path = cumulative_path_length_m(gt);
  std::vector<Pose> est;
  for (std::size_t i = 0; i < gt.size(); ++i) {
    const Eigen::AngleAxisd drift(k_deg * path[i] * std::numbers::pi / 180.0,
                                  Eigen::Vector3d::UnitZ());
    est.push_back(Pose(drift) * gt[i]);
  }
  const RelativePoseError rpe = relative_pose_error(est, gt, 1.0);
  EXPECT_NEAR(rpe.rotation_deg_per_m, k_deg, 1e-6);
  EXPECT_GT(rpe.translation_per_m, 0.0);
}

TEST(Association, GreedyClosestWithinMaxDifference) {
  auto t = [](double s) { return Timestamp::from_seconds(s); };
  const std::vector<Timestamp> first = {t(1.00), t(1.10), t(1.20), t(1.30)};
  // 1.103 is closer to 1.10 than 1.095 is; 1.50 has no partner; 1.21 pairs with 1.20.
  const std::vector<Timestamp> second = {t(0.995), t(1.095), t(1.103), t(1.21), t(1.50)};
  const std::vector<AssociatedIndices> m = associate_by_time(first, second, 0.02);
  const std::vector<AssociatedIndices> expected = {{0, 0}, {1, 2}, {2, 3}};
  EXPECT_EQ(m, expected);
  EXPECT_EQ(nearest_stamp(second, t(1.096), 0.02), std::optional<std::size_t>(1));
  EXPECT_EQ(nearest_stamp(second, t(1.40), 0.02), std::nullopt);
}

}  // namespace
}  // namespace wifislam::eval
