#pragma once
// Poses and edge information for pose-graph tests built by hand (optimiser, pruning).

#include <Eigen/Geometry>

#include "core/pose.hpp"
#include "slam/graph/pose_graph.hpp"

namespace wifislam::slam::test {

/// Diagonal information: one standard deviation for every translation axis, one for rotation.
inline graph::Information6 information(double sigma_m, double sigma_rad) {
  graph::Information6 info = graph::Information6::Zero();
  info.diagonal() << Eigen::Vector3d::Constant(1 / (sigma_m * sigma_m)),
      Eigen::Vector3d::Constant(1 / (sigma_rad * sigma_rad));
  return info;
}

/// A pose in the z = 0 plane, turned `yaw` about z.
inline Pose planar(double x, double y, double yaw) {
  Pose p = Pose::Identity();
  p.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  p.translation() = Eigen::Vector3d(x, y, 0);
  return p;
}

}  // namespace wifislam::slam::test
