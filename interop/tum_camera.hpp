#pragma once
// The three Kinects of the TUM RGB-D benchmark (its "File Formats" page, calibrated RGB
// intrinsics of each Freiburg sequence set), which peers that read TUM folders know by name:
// RTAB-Map's rtabmap-rgbd_dataset takes a sequence's intrinsics from "freiburg1", "freiburg2" or
// "freiburg3" in the folder's name and has no other way in. Values as that tool holds them
// (tools/RgbdDataset/main.cpp), all 640 x 480.

#include <optional>
#include <span>
#include <string>

#include "core/camera_intrinsics.hpp"

namespace wifislam::interop {

struct TumCamera {
  const char* name;  // "freiburg1": what a folder name must contain
  CameraIntrinsics intrinsics;
};

std::span<const TumCamera> tum_cameras();

/// TUM states the values to 0.1 px: a calibration within this of one of them is that camera.
inline constexpr double kTumIntrinsicsTolerancePx = 0.05;

/// The TUM camera whose image size and fx, fy, cx, cy all equal `k`'s (within the tolerance).
std::optional<TumCamera> matching_tum_camera(const CameraIntrinsics& k);

/// The largest difference (px) between `k`'s fx, fy, cx, cy and `camera`'s.
double largest_difference_px(const CameraIntrinsics& k, const TumCamera& camera);

/// "fx 517.3 fy 516.5 cx 318.6 cy 255.3 (640x480)".
std::string describe_intrinsics(const CameraIntrinsics& k);

}  // namespace wifislam::interop
