#include "core/camera_intrinsics.hpp"

#include <cmath>

#include <fmt/format.h>

namespace wifislam {

double CameraIntrinsics::horizontal_fov_rad() const {
  return std::atan2(cx_px + 0.5, fx_px) + std::atan2(width_px - cx_px - 0.5, fx_px);
}

std::optional<IntrinsicsProblem> intrinsics_problem(const CameraIntrinsics& k) {
  for (const auto& [key, f] : {std::pair{"fx_px", k.fx_px}, std::pair{"fy_px", k.fy_px}}) {
    if (!(f > 0.0 && f <= kMaxFocalLengthPx)) {
      return IntrinsicsProblem{key,
                               fmt::format("expected a focal length above 0, up to {:g} px, got {}",
                                           kMaxFocalLengthPx, f)};
    }
  }
  if (!(k.cx_px >= 0.0 && k.cx_px <= k.width_px)) {
    return IntrinsicsProblem{
        "cx_px", fmt::format("expected the principal point in the image (0 to width_px {}), got {}",
                             k.width_px, k.cx_px)};
  }
  if (!(k.cy_px >= 0.0 && k.cy_px <= k.height_px)) {
    return IntrinsicsProblem{"cy_px", fmt::format("expected the principal point in the image (0 to "
                                                  "height_px {}), got {}",
                                                  k.height_px, k.cy_px)};
  }
  return std::nullopt;
}

}  // namespace wifislam
