#pragma once
// imu_groundtruth.csv of a dataset: the IMU's true state at every frame time, the columns of
// EuRoC's state_groundtruth_estimate0 (in seconds, as the TUM files beside it):
//
//   timestamp,p_x_m,p_y_m,p_z_m,q_w,q_x,q_y,q_z,v_x_mps,v_y_mps,v_z_mps,
//   bw_x_radps,bw_y_radps,bw_z_radps,ba_x_mps2,ba_y_mps2,ba_z_mps2
//
// p, q: the IMU frame in the world (IMU to world); v: its velocity in the world frame; bw, ba:
// the gyroscope and accelerometer biases of imu.csv's sample at or before that time. Times
// strictly increase.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/pose.hpp"
#include "core/timestamp.hpp"

namespace wifislam {

struct ImuGroundTruth {
  Timestamp time;
  Pose imu_to_world = Pose::Identity();
  Eigen::Vector3d velocity_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_bias_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_bias_mps2 = Eigen::Vector3d::Zero();
};

/// The header line (without newline).
std::string imu_groundtruth_csv_header();
/// One row, ending in '\n' (positions and quaternions exact, the rest with 9 significant digits).
std::string format_imu_groundtruth_csv_row(const ImuGroundTruth& state);

/// All rows of a file. Throws ParseError("file:line", column, ...) for a wrong header or field
/// count, a field that is not a finite number, a quaternion of zero length, or a time that does
/// not increase; IoError when the file cannot be read.
std::vector<ImuGroundTruth> read_imu_groundtruth_csv(const std::string& path);

}  // namespace wifislam
