#pragma once
// calibration.yaml of a dataset: camera intrinsics and frame rate, depth PNG scale, where the
// camera sits on the robot base, the odometry rate, and the parameters of the simulated sensors
// (kept as text groups so core need not know the simulator's structs).
//
//   camera: {width_px: 640, height_px: 480, fx_px: 525, fy_px: 525, cx_px: 319.5, cy_px: 239.5,
//            fps: 30}
//   depth: {units_per_metre: 5000}
//   camera_in_base: {translation_m: [0, 0, 0.5], rotation_xyzw: [-0.5, 0.5, -0.5, 0.5]}
//   odometry: {rate_hz: 50}
//   imu: {rate_hz: 200, imu_in_base: {translation_m: [...], rotation_xyzw: [...]},
//         T_cam_imu: [16 numbers, row-major], gyroscope_noise_density: ..., ...}
//   sensor_model:
//     depth_sensor: {noise: true, ...}

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/camera_intrinsics.hpp"
#include "core/dataset_format.hpp"
#include "core/pose.hpp"

namespace wifislam {

struct CalibrationGroup {
  std::string name;
  std::vector<std::pair<std::string, std::string>> values;  // key -> scalar text
};

/// The IMU of imu.csv (absent from datasets generated without one). The noise parameters are
/// continuous-time, in the Kalibr/Allan convention (Kalibr's imu.yaml keys): white-noise densities
/// and bias random walks.
struct ImuCalibration {
  double rate_hz = 200.0;
  Pose imu_in_base = Pose::Identity();
  double gyroscope_noise_density = 0.0;      // rad / s / sqrt(Hz)
  double gyroscope_random_walk = 0.0;        // rad / s^2 / sqrt(Hz)
  double accelerometer_noise_density = 0.0;  // m / s^2 / sqrt(Hz)
  double accelerometer_random_walk = 0.0;    // m / s^3 / sqrt(Hz)
};

struct DatasetCalibration {
  CameraIntrinsics intrinsics;
  double camera_fps = 30.0;
  double depth_units_per_metre = dataset::kDepthUnitsPerMetre;
  Pose camera_in_base = Pose::Identity();  // camera optical frame in the robot base frame
  std::optional<double> odometry_rate_hz;
  std::optional<ImuCalibration> imu;
  std::vector<CalibrationGroup> sensor_model;

  /// Kalibr's T_cam_imu: IMU frame -> camera optical frame (p_cam = T_cam_imu p_imu). Needs imu.
  Pose camera_from_imu() const { return camera_in_base.inverse() * imu->imu_in_base; }
};

std::string calibration_to_yaml(const DatasetCalibration& calibration);
/// Throws IoError (unreadable) or ParseError naming the file, line and key.
DatasetCalibration read_calibration_yaml(const std::filesystem::path& path);

}  // namespace wifislam
