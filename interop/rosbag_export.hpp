#pragma once
// A dataset as one ROS 1 bag (`export --for rosbag`), with the topics and frames of the TUM RGB-D
// benchmark's bags where they have one:
//
//   /camera/rgb/image_color        sensor_msgs/Image rgb8, frame openni_rgb_optical_frame
//   /camera/rgb/camera_info        sensor_msgs/CameraInfo (pinhole, no distortion)
//   /camera/depth/image            sensor_msgs/Image 32FC1, metres, NaN where the sensor has no
//                                  reading (TUM's convention); registered to the colour camera,
//                                  so in its frame
//   /camera/depth/camera_info      sensor_msgs/CameraInfo (the same camera)
//   /tf                            world -> kinect at every frame (the camera's ground truth, as
//                                  TUM's motion capture names it) and odom -> base_link at every
//                                  odometry reading
//   /tf_static                     base_link -> openni_rgb_optical_frame (the camera mount) and
//                                  base_link -> imu_link; latched, as tf2 publishes it
//   /imu                           sensor_msgs/Imu, frame imu_link, no orientation
//   /odom                          nav_msgs/Odometry: the wheel odometry, odom -> base_link, its
//                                  twist the base's mean velocity since the previous reading (in
//                                  base_link); covariances zero, as the dataset holds no noise
//                                  figures
//   /ground_truth/pose             geometry_msgs/PoseStamped: the camera's optical frame in world
//   /wifi/scan                     wifislam_msgs/WifiScan (interop/rosbag/WifiScan.msg)
//
// The ground truth is a tree of its own (world -> kinect), apart from odom -> base_link -> camera,
// as in TUM's bags: RTAB-Map's ground_truth_frame_id / ground_truth_base_frame_id (world, kinect)
// read it from there. Each topic's header.seq counts its messages from 0.
//
// LZ4 chunk compression (rosbag's own; `rosbag decompress` undoes it).

#include <filesystem>
#include <string>

#include "core/dataset_calibration.hpp"

namespace wifislam::interop {

inline constexpr const char* kBagFile = "dataset.bag";

/// Checks what the bag needs before anything is written: ground truth, and Unix stamps that ROS
/// time holds. Throws InvalidInputError (exit 2) naming the dataset.
void check_rosbag_input(const std::filesystem::path& dataset);

/// Writes `staging`/dataset.bag from the dataset (its images decoded frame by frame); returns the
/// number of messages.
std::int64_t write_rosbag(const std::filesystem::path& dataset,
                          const DatasetCalibration& calibration,
                          const std::filesystem::path& staging, bool verify_checksums);

}  // namespace wifislam::interop
