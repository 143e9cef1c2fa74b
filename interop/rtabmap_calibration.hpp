#pragma once
// RTAB-Map's own camera calibration file for an RGB-D images folder: what `CameraModel::save`
// writes and `CameraRGBDImages::init(dir, "rtabmap_calib")` reads back (OpenCV FileStorage,
// "%YAML:1.0", the ROS camera_info keys plus RTAB-Map's `local_transform`):
//
//   camera_name, image_width, image_height
//   camera_matrix            3x3  fx 0 cx / 0 fy cy / 0 0 1
//   distortion_coefficients  1x5  zeros (plumb_bob: the rendered images have no distortion)
//   distortion_model         plumb_bob
//   rectification_matrix     3x3  identity
//   projection_matrix        3x4  fx 0 cx 0 / 0 fy cy 0 / 0 0 1 0
//   local_transform          3x4  the optical rotation rtabmap-rgbd_dataset itself uses (camera
//                                 base frame x forward, y left, z up -> optical frame)
//
// rtabmap-rgbd_dataset first writes its own file of that name when the folder's name holds
// "freiburg1/2/3" (then with TUM's Kinect intrinsics) and otherwise prints "Dataset ... is not
// supported" and reads ours, so ours is what it uses whatever the folder is called, unless the
// name says freiburgN (peer_export warns when that camera is not the dataset's).

#include <string>

#include "core/camera_intrinsics.hpp"

namespace wifislam::interop {

/// The file's name for the tool's default --output_name "rtabmap" (`<output_name>_calib.yaml`).
inline constexpr const char* kRtabmapCalibration = "rtabmap_calib.yaml";
/// The camera_name inside it (CameraModel names the file after it).
inline constexpr const char* kRtabmapCameraName = "rtabmap_calib";

/// The file's text for a pinhole camera without distortion.
std::string rtabmap_calibration_yaml(const CameraIntrinsics& intrinsics);

}  // namespace wifislam::interop
