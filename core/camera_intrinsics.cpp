#include "core/camera_intrinsics.hpp"

#include <cmath>

namespace wifislam {

double CameraIntrinsics::horizontal_fov_rad() const {
  return std::atan2(cx_px + 0.5, fx_px) + std::atan2(width_px - cx_px - 0.5, fx_px);
}

}  // namespace wifislam
