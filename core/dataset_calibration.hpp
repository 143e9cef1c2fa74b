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
//   sensor_model:
//     depth_sensor: {noise: true, ...}

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/camera_intrinsics.hpp"
#include "core/pose.hpp"

namespace wifislam {

struct CalibrationGroup {
  std::string name;
  std::vector<std::pair<std::string, std::string>> values;  // key -> scalar text
};

struct DatasetCalibration {
  CameraIntrinsics intrinsics;
  double camera_fps = 30.0;
  double depth_units_per_metre = 5000.0;
  Pose camera_in_base = Pose::Identity();  // camera optical frame in the robot base frame
  std::optional<double> odometry_rate_hz;
  std::vector<CalibrationGroup> sensor_model;
};

std::string calibration_to_yaml(const DatasetCalibration& calibration);
/// Throws IoError (unreadable) or ParseError naming the file, line and key.
DatasetCalibration read_calibration_yaml(const std::filesystem::path& path);

}  // namespace wifislam
