#include "slam/frontend/keyframe_schedule.hpp"

#include <Eigen/Geometry>

namespace wifislam::slam::frontend {

bool KeyframeSchedule::due(std::int64_t elapsed_ns, const Pose& keyframe_from_frame) const {
  constexpr double kToleranceS = 1e-3;
  if (static_cast<double>(elapsed_ns) * 1e-9 < period_s - kToleranceS) return false;
  return keyframe_from_frame.translation().norm() >= min_translation_m ||
         Eigen::AngleAxisd(keyframe_from_frame.linear()).angle() >= min_rotation_rad;
}

}  // namespace wifislam::slam::frontend
