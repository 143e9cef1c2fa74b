#pragma once
// The visual transformation between two RGB-D frames (paper, "RGBD SLAM"): ORB matches with the
// ratio test, 3-D/2-D RANSAC (cv::solvePnPRansac: 3-D points of frame b, keypoints of frame a),
// Levenberg-Marquardt refinement on the inliers, and an information matrix from the reprojection
// Jacobians. The two parameters the paper tunes are `min_matches` and `inlier_distance`.

#include <Eigen/Core>

#include "core/camera_intrinsics.hpp"
#include "core/pose.hpp"
#include "slam/feature/frame_features.hpp"
#include "slam/match/descriptor_matcher.hpp"
#include "slam/util/instrumentation.hpp"

namespace wifislam::slam {

struct VisualTransformOptions {
  MatchOptions matching;
  /// Minimum RANSAC inliers to accept a transformation (paper's `min_matches`; RGBDSLAMv2
  /// default 20). Lower accepts more true and more false loop closures (perceptual aliasing).
  int min_matches = 20;
  /// RANSAC inlier threshold: reprojection error in PIXELS of a frame-b point in frame a (paper's
  /// `inlier_distance`). Larger tolerates depth noise but lets wrong matches agree.
  double inlier_distance = 3.0;
  /// Maximum RANSAC iterations (RGBDSLAMv2 `ransac_iterations` 200); stops earlier once
  /// `ransac_confidence` is reached.
  int ransac_iterations = 200;
  /// Confidence for RANSAC's adaptive stopping; must be below 1 (OpenCV asserts on 1.0).
  double ransac_confidence = 0.99;
  /// Floor of the reprojection noise used for the information matrix (pixels): keeps a
  /// noise-free render from claiming infinite certainty.
  double min_reprojection_sigma_px = 0.5;
  /// Depth noise model for the information matrix: sigma_z = coeff * z^2 (Kinect v1: 1.425e-3 per
  /// metre, K. Khoshelham and S. O. Elberink, Sensors 12(2), 2012). Far points then weigh less,
  /// so an edge resting on distant, coarsely quantised depth does not claim centimetre accuracy.
  double depth_noise_coeff_per_m = 1.425e-3;
  /// Where frame a also measured depth, an inlier's predicted depth must agree with it within
  /// this many standard deviations (of both readings) plus 2 cm; 0 turns the check off (pure
  /// 3-D/2-D). Rejects poses that are right in 2-D only (planar mirror solutions, aliasing).
  double depth_consistency_sigmas = 3.0;
};

/// Edge measurement between two frames a and b.
struct VisualTransformation {
  bool accepted = false;
  /// Pose of frame b in frame a (maps points of b into a): X_a = a_from_b * X_b.
  Pose a_from_b = Pose::Identity();
  int matches = 0;  // ratio-test matches with depth in b
  int inliers = 0;
  double rms_reprojection_px = 0.0;
  /// Information of the pose error in the pose graph's residual convention
  /// ([translation; rotation] of a_from_b expressed in frame a; see optimize/).
  Eigen::Matrix<double, 6, 6> information = Eigen::Matrix<double, 6, 6>::Zero();
};

/// Estimates the transformation between two frames. Timing goes to `instrumentation` under
/// "matching" and "ransac"; one "ransac_runs" count per RANSAC call.
VisualTransformation estimate_visual_transformation(const FrameFeatures& a, const FrameFeatures& b,
                                                    const CameraIntrinsics& intrinsics,
                                                    const VisualTransformOptions& options,
                                                    Instrumentation& instrumentation);

/// Information matrix (pose graph convention) of a_from_b from the inlier reprojection
/// Jacobians: sum J^T W J, where W^-1 = sigma_px^2 I + the image-a covariance of the point's depth
/// error along frame b's viewing ray (sigma_z = depth_noise_coeff_per_m z_b^2).
Eigen::Matrix<double, 6, 6> pnp_information(const std::vector<Eigen::Vector3d>& points_in_b_m,
                                            const Pose& a_from_b,
                                            const CameraIntrinsics& intrinsics, double sigma_px,
                                            double depth_noise_coeff_per_m);

}  // namespace wifislam::slam
