#pragma once
// Final refinement of a 3-D/2-D pose with each correspondence weighted by its own uncertainty.
// A 3-D point from a Kinect-like depth image is uncertain along its viewing ray by
// sigma_z = c z^2, so distant points (coarse depth) should count less than near ones; OpenCV's
// solvePnPRefineLM weighs all alike. Solved with Ceres (quaternion manifold), a few iterations.

#include <vector>

#include <Eigen/Core>

#include "core/camera_intrinsics.hpp"
#include "core/pose.hpp"

namespace wifislam::slam::solve {

/// 2x2 covariance (pixels^2) of the projection into frame a of point `point_b_m` of frame b:
/// sigma_px^2 I plus its depth error along b's ray, sigma_z = depth_noise_coeff_per_m z_b^2.
Eigen::Matrix2d projected_point_covariance(const Eigen::Vector3d& point_b_m, const Pose& a_from_b,
                                           const CameraIntrinsics& intrinsics, double sigma_px,
                                           double depth_noise_coeff_per_m);

/// Refines a_from_b minimising sum |C_i^-1/2 (project(a_from_b X_b,i) - u_a,i)|^2 with the
/// covariances C_i evaluated at `initial`. Returns `initial` unchanged when Ceres fails.
Pose refine_pose_weighted(const std::vector<Eigen::Vector3d>& points_b_m,
                          const std::vector<Eigen::Vector2d>& pixels_a, const Pose& initial,
                          const CameraIntrinsics& intrinsics, double sigma_px,
                          double depth_noise_coeff_per_m, int max_iterations = 10);

}  // namespace wifislam::slam::solve
