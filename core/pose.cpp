#include "core/pose.hpp"

#include <cmath>

namespace wifislam {

Pose pose_from_translation_quaternion(const Eigen::Vector3d& t_m, const Eigen::Quaterniond& q) {
  Pose pose = Pose::Identity();
  pose.linear() = q.normalized().toRotationMatrix();
  pose.translation() = t_m;
  return pose;
}

Eigen::Matrix3d optical_to_body_rotation() {
  // Columns are the optical axes expressed in the body frame:
  // optical x (right) = body -y, optical y (down) = body -z, optical z (forward) = body +x.
  Eigen::Matrix3d r;
  r << 0, 0, 1,  //
      -1, 0, 0,  //
      0, -1, 0;
  return r;
}

Pose camera_pose_from_planar(double x_m, double y_m, double yaw_rad, double height_m,
                             double pitch_rad) {
  Pose body = Pose::Identity();
  // Pitch about the body's y (left) axis: positive pitch looks up, i.e. rotates +x towards +z,
  // which is a negative rotation about +y.
  body.linear() = (Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(-pitch_rad, Eigen::Vector3d::UnitY()))
                      .toRotationMatrix();
  body.translation() = Eigen::Vector3d(x_m, y_m, height_m);
  Pose camera = body;
  camera.linear() = body.linear() * optical_to_body_rotation();
  return camera;
}

double camera_yaw_rad(const Pose& camera_to_world) {
  const Eigen::Vector3d forward = camera_to_world.linear().col(2);
  return std::atan2(forward.y(), forward.x());
}

double rotation_angle_rad(const Pose& a, const Pose& b) {
  const Eigen::AngleAxisd aa(a.linear().transpose() * b.linear());
  return std::abs(aa.angle());
}

double translation_distance_m(const Pose& a, const Pose& b) {
  return (a.translation() - b.translation()).norm();
}

}  // namespace wifislam
