#include "interop/tum_camera.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

namespace wifislam::interop {

namespace {

constexpr CameraIntrinsics kinect(double fx, double fy, double cx, double cy) {
  return CameraIntrinsics{640, 480, fx, fy, cx, cy};
}

constexpr std::array<TumCamera, 3> kCameras = {{
    {"freiburg1", kinect(517.3, 516.5, 318.6, 255.3)},
    {"freiburg2", kinect(520.9, 521.0, 325.1, 249.7)},
    {"freiburg3", kinect(535.4, 539.2, 320.1, 247.6)},
}};

}  // namespace

std::span<const TumCamera> tum_cameras() { return kCameras; }

double largest_difference_px(const CameraIntrinsics& k, const TumCamera& camera) {
  const CameraIntrinsics& t = camera.intrinsics;
  return std::max({std::abs(k.fx_px - t.fx_px), std::abs(k.fy_px - t.fy_px),
                   std::abs(k.cx_px - t.cx_px), std::abs(k.cy_px - t.cy_px)});
}

std::optional<TumCamera> matching_tum_camera(const CameraIntrinsics& k) {
  for (const TumCamera& camera : kCameras) {
    if (k.width_px == camera.intrinsics.width_px && k.height_px == camera.intrinsics.height_px &&
        largest_difference_px(k, camera) <= kTumIntrinsicsTolerancePx) {
      return camera;
    }
  }
  return std::nullopt;
}

std::string describe_intrinsics(const CameraIntrinsics& k) {
  return fmt::format("fx {} fy {} cx {} cy {} ({}x{})", k.fx_px, k.fy_px, k.cx_px, k.cy_px,
                     k.width_px, k.height_px);
}

}  // namespace wifislam::interop
