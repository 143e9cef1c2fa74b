#pragma once
// ORB-SLAM2's settings file for its RGB-D examples (Examples/RGB-D/TUM1.yaml's keys, in its order,
// OpenCV FileStorage's "%YAML:1.0"), filled with a dataset's own calibration instead of a TUM
// Kinect's: pinhole intrinsics without distortion (our images have none), the frame rate,
// Camera.bf = depth baseline x fx, Camera.RGB 1 and ThDepth 40 as TUM1.yaml has them, the
// dataset's depth units per metre as DepthMapFactor (5000, TUM's), and TUM1.yaml's ORB extractor
// and viewer defaults.

#include <string>

#include "core/dataset_calibration.hpp"

namespace wifislam::interop {

/// The Kinect v1's projector-to-camera baseline (the ICL-NUIM / simkinect Kinect model), used when
/// the calibration does not state the depth sensor's own.
inline constexpr double kKinectV1BaselineM = 0.075;

/// The depth sensor's baseline from calibration.yaml's sensor_model (depth_sensor.baseline_m),
/// or kKinectV1BaselineM.
double depth_baseline_m(const DatasetCalibration& calibration);

/// The settings file's text.
std::string orbslam2_settings_yaml(const DatasetCalibration& calibration);

}  // namespace wifislam::interop
