#pragma once
// Least-squares alignment of an estimated trajectory onto ground truth: Umeyama (1991), via
// Eigen::umeyama (SVD with the reflection fix; the same rigid solution as Horn's method in TUM's
// evaluate_ate.py). Rigid by default; with scale for monocular-style comparisons (evo -as).

#include <optional>
#include <string_view>

#include <Eigen/Core>

#include "core/pose.hpp"

namespace wifislam::eval {

/// What the estimate may be moved by before its error is measured: nothing (the estimate is
/// already in the ground-truth frame), a rigid motion (SE(3): evaluate_ate.py, evo -a; right for
/// RGB-D, whose depth fixes the scale) or a similarity (Sim(3): evo -as, for monocular systems).
enum class AlignmentMode { kNone, kSe3, kSim3 };

/// "none", "se3", "sim3".
const char* to_string(AlignmentMode mode);
/// Inverse of to_string; nullopt for anything else.
std::optional<AlignmentMode> parse_alignment_mode(std::string_view text);

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
