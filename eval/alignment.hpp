#pragma once
// Least-squares alignment of an estimated trajectory onto ground truth: Umeyama (1991), via
// Eigen::umeyama (SVD with the reflection fix; the same rigid solution as Horn's method in TUM's
// evaluate_ate.py). Rigid by default; with scale for monocular-style comparisons (evo -as).

#include <Eigen/Core>

#include "core/pose.hpp"

namespace wifislam::eval {

struct Alignment {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();
  double scale = 1.0;

  Eigen::Vector3d apply(const Eigen::Vector3d& p) const {
    return scale * (rotation * p) + translation_m;
  }
  /// Pose mapped into the target frame (rotation composed, position scaled and moved).
  Pose apply(const Pose& pose) const;
};

/// The transform x -> s R x + t minimising sum |target_i - (s R source_i + t)|^2 (s = 1 unless
/// `with_scale`). Throws InvalidInputError with fewer than 3 point pairs or a size mismatch.
Alignment align_points(const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target,
                       bool with_scale);

}  // namespace wifislam::eval
