#include "eval/trajectory_error.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "core/median.hpp"

namespace wifislam::eval {

AbsoluteTrajectoryError absolute_trajectory_error(const std::vector<Pose>& estimated,
                                                  const std::vector<Pose>& ground_truth,
                                                  AlignmentMode mode) {
  if (estimated.size() != ground_truth.size()) {
    throw InvalidInputError("ATE: estimated and ground-truth pose counts differ");
  }
  const auto n = static_cast<Eigen::Index>(estimated.size());
  Eigen::Matrix3Xd est(3, n), gt(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    est.col(i) = estimated[static_cast<std::size_t>(i)].translation();
    gt.col(i) = ground_truth[static_cast<std::size_t>(i)].translation();
  }
  AbsoluteTrajectoryError out;
  // kNone keeps the identity: the estimate is scored in its own frame.
  if (mode != AlignmentMode::kNone) {
    out.alignment = align_points(est, gt, mode == AlignmentMode::kSim3);
  } else if (n < 3) {
    throw InvalidInputError("ATE: needs at least 3 associated poses, got " + std::to_string(n));
  }
  out.errors_m.resize(estimated.size());
  double sum = 0.0, sum_sq = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double e = (gt.col(i) - out.alignment.apply(Eigen::Vector3d(est.col(i)))).norm();
    out.errors_m[static_cast<std::size_t>(i)] = e;
    sum += e;
    sum_sq += e * e;
    out.max_m = std::max(out.max_m, e);
  }
  out.rmse_m = std::sqrt(sum_sq / static_cast<double>(n));
  out.mean_m = sum / static_cast<double>(n);
  out.median_m = median(out.errors_m);
  return out;
}

AbsoluteTrajectoryError absolute_trajectory_error(const std::vector<Pose>& estimated,
                                                  const std::vector<Pose>& ground_truth,
                                                  bool with_scale) {
  return absolute_trajectory_error(estimated, ground_truth,
                                   with_scale ? AlignmentMode::kSim3 : AlignmentMode::kSe3);
}

std::vector<double> cumulative_path_length_m(const std::vector<Pose>& poses) {
  std::vector<double> length(poses.size(), 0.0);
  for (std::size_t i = 1; i < poses.size(); ++i) {
    length[i] = length[i - 1] + (poses[i].translation() - poses[i - 1].translation()).norm();
  }
  return length;
}

RelativePoseError relative_pose_error(const std::vector<Pose>& estimated,
                                      const std::vector<Pose>& ground_truth, double delta_m,
                                      double estimate_scale) {
  if (estimated.size() != ground_truth.size()) {
    throw InvalidInputError("RPE: estimated and ground-truth pose counts differ");
  }
  const std::vector<double> path = cumulative_path_length_m(ground_truth);
  RelativePoseError out;
  double trans_per_m = 0.0, rot_per_m = 0.0, trans_sq = 0.0, rot_sq = 0.0;
  std::size_t j = 0;
  for (std::size_t i = 0; i < ground_truth.size(); ++i) {
    j = std::max(j, i + 1);
    while (j < ground_truth.size() && path[j] - path[i] < delta_m) ++j;
    if (j >= ground_truth.size()) break;
    const double length_m = path[j] - path[i];
    const Pose gt_rel = ground_truth[i].inverse() * ground_truth[j];
    Pose est_rel = estimated[i].inverse() * estimated[j];
    est_rel.translation() *= estimate_scale;
    const Pose error = gt_rel.inverse() * est_rel;
    const double t = error.translation().norm();
    const double r =
        Eigen::AngleAxisd(Eigen::Matrix3d(error.linear())).angle() * 180.0 / std::numbers::pi;
    trans_per_m += t / length_m;
    rot_per_m += r / length_m;
    trans_sq += t * t;
    rot_sq += r * r;
    ++out.pairs;
  }
  if (out.pairs > 0) {
    const double n = static_cast<double>(out.pairs);
    out.translation_per_m = trans_per_m / n;
    out.rotation_deg_per_m = rot_per_m / n;
    out.translation_rmse_m = std::sqrt(trans_sq / n);
    out.rotation_rmse_deg = std::sqrt(rot_sq / n);
  }
  return out;
}

}  // namespace wifislam::eval
