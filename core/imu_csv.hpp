#pragma once
// imu.csv of a dataset: one row per IMU sample, in the IMU frame (calibration.yaml: imu):
//
//   timestamp,w_x_radps,w_y_radps,w_z_radps,a_x_mps2,a_y_mps2,a_z_mps2
//   1700000000.005000,0.000114,-0.00021,0.6000003,0.0021,0.30004,9.8086
//
// timestamp in seconds, as the TUM files beside it (6 decimals: whole microseconds); w angular
// velocity, a specific force (gravity included: +9.81 up at rest). Each row is the mean over the
// time since the row before (sim/robot/imu_model.hpp). Times strictly increase.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/timestamp.hpp"

namespace wifislam {

struct ImuReading {
  Timestamp time;
  Eigen::Vector3d angular_velocity_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d specific_force_mps2 = Eigen::Vector3d::Zero();
};

/// The header line (without newline).
std::string imu_csv_header();
/// One row, ending in '\n'; values with 9 significant digits.
std::string format_imu_csv_row(const ImuReading& reading);

/// All readings of a file. Throws ParseError("file:line", column, ...) for a wrong header, a
/// wrong field count, a field that is not a finite number, a value beyond what any IMU reads
/// (1e6 m/s^2 or rad/s: a corrupt row), or a time that does not increase;
/// IoError when the file cannot be read.
std::vector<ImuReading> read_imu_csv(const std::string& path);

}  // namespace wifislam
