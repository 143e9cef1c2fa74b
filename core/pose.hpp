#pragma once
// Pose helpers. Poses are camera-to-world (or body-to-world) rigid transforms,
// world frame x east, y north, z up; camera optical frame x right, y down, z forward.

#include <Eigen/Geometry>

namespace wifislam {

using Pose = Eigen::Isometry3d;

/// Pose from a translation and a (not necessarily normalised) quaternion.
Pose pose_from_translation_quaternion(const Eigen::Vector3d& t_m, const Eigen::Quaterniond& q);

/// Rotation taking camera optical axes (x right, y down, z forward) to a body frame whose
/// x points forward, y left, z up. Multiply a body-to-world pose by this to get camera-to-world.
Eigen::Matrix3d optical_to_body_rotation();

/// Camera-to-world pose of a camera at (x, y, height) looking horizontally along `yaw_rad`
/// (counter-clockwise from +x), pitched up by `pitch_rad` (positive = looking up).
Pose camera_pose_from_planar(double x_m, double y_m, double yaw_rad, double height_m,
                             double pitch_rad = 0.0);

/// Yaw (counter-clockwise from +x, radians) of the viewing direction of a camera pose.
double camera_yaw_rad(const Pose& camera_to_world);

/// Angle of the rotation between two poses (radians, in [0, pi]).
double rotation_angle_rad(const Pose& a, const Pose& b);

/// Distance between the translations of two poses (metres).
double translation_distance_m(const Pose& a, const Pose& b);

}  // namespace wifislam
