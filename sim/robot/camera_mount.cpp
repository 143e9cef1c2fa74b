#include "sim/robot/camera_mount.hpp"

#include <numbers>

namespace wifislam::sim::robot {

CameraMount::CameraMount(const scene::CameraSpec& spec)
    : height_m_(spec.height_m), pitch_rad_(spec.pitch_deg * std::numbers::pi / 180.0) {}

Pose CameraMount::camera_in_base() const {
  return camera_pose_from_planar(0.0, 0.0, 0.0, height_m_, pitch_rad_);
}

Pose CameraMount::camera_to_world(const RobotState& state) const {
  return camera_pose_from_planar(state.position_m.x(), state.position_m.y(), state.heading_rad,
                                 height_m_, pitch_rad_);
}

}  // namespace wifislam::sim::robot
