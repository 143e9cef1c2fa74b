#pragma once
// Pinhole intrinsics of an RGB-D camera (pixels). Default: Kinect v1 as in the TUM RGB-D
// benchmark's default calibration (640x480, fx = fy = 525, cx = 319.5, cy = 239.5).

#include <optional>
#include <string>

#include <Eigen/Core>

namespace wifislam {

struct CameraIntrinsics {
  int width_px = 640;
  int height_px = 480;
  double fx_px = 525.0;
  double fy_px = 525.0;
  double cx_px = 319.5;
  double cy_px = 239.5;

  static CameraIntrinsics kinect_v1() { return {}; }

  Eigen::Matrix3d matrix() const {
    Eigen::Matrix3d k;
    k << fx_px, 0, cx_px, 0, fy_px, cy_px, 0, 0, 1;
    return k;
  }
  /// Point in the optical frame for pixel (u, v) at depth z (along the optical axis).
  Eigen::Vector3d back_project(double u_px, double v_px, double z_m) const {
    return {(u_px - cx_px) * z_m / fx_px, (v_px - cy_px) * z_m / fy_px, z_m};
  }
  /// Horizontal field of view (radians).
  double horizontal_fov_rad() const;

  friend bool operator==(const CameraIntrinsics&, const CameraIntrinsics&) = default;
};

/// Beyond any depth camera: a 3.7 degree view across 65535 pixels.
inline constexpr double kMaxFocalLengthPx = 1e6;

/// What makes `k` not a camera, if anything: {key (fx_px, cx_px, ...), why}. The focal lengths
/// lie in (0, kMaxFocalLengthPx], the principal point in the image. Scenes and calibration.yaml
/// are checked by this one rule, so a dataset generated from a valid scene always reads back.
struct IntrinsicsProblem {
  std::string key, why;
};
std::optional<IntrinsicsProblem> intrinsics_problem(const CameraIntrinsics& k);

}  // namespace wifislam
