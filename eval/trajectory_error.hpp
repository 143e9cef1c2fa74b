#pragma once
// Trajectory error of associated (estimated, ground-truth) pose pairs.
//
// ATE (absolute trajectory error, TUM evaluate_ate.py / the paper's metric): align the estimated
// positions onto ground truth (alignment.hpp), then the error of pair i is |gt_i - A(est_i)|;
// RMSE, mean, median and max over all pairs.
//
// RPE (relative pose error, drift): for each pair i, j is the first later pair whose
// ground-truth path length from i reaches `delta_m`; the error is E = inv(gt_i^-1 gt_j) *
// (est_i^-1 est_j) (estimated translation scaled by the alignment scale). Reported per metre
// travelled: the mean over pairs of |trans(E)| / L_ij and of angle(E) [deg] / L_ij, where L_ij is
// that pair's ground-truth path length (>= delta_m), plus the RMSE of |trans(E)| and angle(E).

#include <cstddef>
#include <vector>

#include "core/pose.hpp"
#include "eval/alignment.hpp"

namespace wifislam::eval {

struct AbsoluteTrajectoryError {
  Alignment alignment;
  std::vector<double> errors_m;  // per pair, in input order
  double rmse_m = 0.0, mean_m = 0.0, median_m = 0.0, max_m = 0.0;
};

/// `estimated[i]` and `ground_truth[i]` are one associated pair. Throws InvalidInputError with
/// fewer than 3 pairs.
AbsoluteTrajectoryError absolute_trajectory_error(const std::vector<Pose>& estimated,
                                                  const std::vector<Pose>& ground_truth,
                                                  AlignmentMode mode);
/// The same, rigid (`with_scale` false) or with scale.
AbsoluteTrajectoryError absolute_trajectory_error(const std::vector<Pose>& estimated,
                                                  const std::vector<Pose>& ground_truth,
                                                  bool with_scale);

struct RelativePoseError {
  std::size_t pairs = 0;  // 0 when the ground truth never travels delta_m
  double translation_per_m = 0.0;
  double rotation_deg_per_m = 0.0;
  double translation_rmse_m = 0.0;
  double rotation_rmse_deg = 0.0;
};

RelativePoseError relative_pose_error(const std::vector<Pose>& estimated,
                                      const std::vector<Pose>& ground_truth, double delta_m,
                                      double estimate_scale = 1.0);

/// Cumulative path length of the poses' positions (first = 0).
std::vector<double> cumulative_path_length_m(const std::vector<Pose>& poses);

}  // namespace wifislam::eval
