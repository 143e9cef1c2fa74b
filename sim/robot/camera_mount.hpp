#pragma once
// The RGB-D camera on the robot: `height_m` above the floor, over the base origin, looking along
// the direction of travel and pitched up by `pitch_deg` (Kinect on a TurtleBot: 0.5 m, level).

#include "core/pose.hpp"
#include "sim/robot/motion_profile.hpp"
#include "sim/scene/scene.hpp"

namespace wifislam::sim::robot {

class CameraMount {
 public:
  explicit CameraMount(const scene::CameraSpec& spec);
  CameraMount(double height_m, double pitch_rad) : height_m_(height_m), pitch_rad_(pitch_rad) {}

  /// Camera (optical frame) in the robot base frame.
  Pose camera_in_base() const;
  /// Camera-to-world pose (optical frame) for a robot state.
  Pose camera_to_world(const RobotState& state) const;

  double height_m() const { return height_m_; }
  double pitch_rad() const { return pitch_rad_; }

 private:
  double height_m_ = 0.5;
  double pitch_rad_ = 0.0;
};

}  // namespace wifislam::sim::robot
