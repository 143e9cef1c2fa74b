#pragma once
// Do two keyframes see the same place? Decided from exact ground truth: the ground-truth poses
// and the dataset's depth images.
//
// First a cheap geometric bound (camera distance and the angle between the optical axes). Then,
// with depth: A's depth pixels (a grid of `overlap_sample_stride_px`) are back-projected with A's
// ground-truth pose and projected into B; a sample lands when it falls inside B's image in front
// of the camera and B's own depth at that pixel (nearest pixel of a grid of
// `overlap_lookup_stride_px`) agrees with the sample's depth in B within
// max(overlap_depth_tolerance_m, overlap_depth_tolerance_rel x depth), i.e. it is neither
// occluded nor missing in B. The views overlap when the fraction of A's samples landing in B, or
// of B's samples landing in A, is at least `overlap_min_fraction`. Without depth images the
// geometric bound alone decides (and the report says so).

#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/camera_intrinsics.hpp"
#include "core/pose.hpp"
#include "eval/eval_options.hpp"

namespace wifislam::eval {

/// What one keyframe's depth image contributes to overlap tests (small: decimated grids).
struct DepthView {
  std::vector<Eigen::Vector3f> samples_camera_m;  // back-projected sample pixels (camera frame)
  cv::Mat lookup_depth_m;  // CV_32FC1, pixel (r, c) = depth at (r, c) x stride
  int lookup_stride_px = 1;
};

/// Builds a DepthView from a full depth image in metres (CV_32FC1, 0 = no reading).
DepthView make_depth_view(const cv::Mat& depth_m, const CameraIntrinsics& intrinsics,
                          const EvalOptions& options);

/// Fraction of `a`'s samples that land in `b` (0 when `a` has no samples).
double landing_fraction(const DepthView& a, const Pose& a_to_world, const DepthView& b,
                        const Pose& b_to_world, const CameraIntrinsics& intrinsics,
                        const EvalOptions& options);

struct ViewOverlap {
  double distance_m = 0.0;
  double angle_deg = 0.0;  // between the optical axes
  bool within_geometric_bound = false;
  bool depth_checked = false;  // false: geometric bound only (no depth, or bound failed)
  double fraction = 0.0;       // A in B, or B in A when A in B falls short; 0 = not checked
  bool overlap = false;
};

/// `a_depth` / `b_depth` may be null (no depth image): the geometric bound decides.
ViewOverlap view_overlap(const Pose& a_to_world, const DepthView* a_depth, const Pose& b_to_world,
                         const DepthView* b_depth, const CameraIntrinsics& intrinsics,
                         const EvalOptions& options);

}  // namespace wifislam::eval
