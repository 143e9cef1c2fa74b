#pragma once
// A dataset folder laid out the way a peer's own dataset tool reads one, without copying an image:
// every image in the export is a relative symbolic link to the dataset's file (so the export and
// the dataset may move or be mounted together, e.g. into a container, and a 50 000-frame export
// costs a few MB), plus the few text files the tool needs.
//
//   rtabmap   RTAB-Map's rtabmap-rgbd_dataset <dir>:
//               rgb_sync/<t>.png, depth_sync/<t>.png   each associated pair under the rgb stamp
//                                                       <t> (the tool reads times from the names
//                                                       and pairs the two folders by order)
//               groundtruth.txt                        link to the dataset's (RMSE in its report)
//               rtabmap_calib.yaml                     the dataset's intrinsics in RTAB-Map's own
//                                                       calibration format (rtabmap_calibration)
//             The tool reads that file whatever the folder is called, unless the name holds
//             "freiburg1/2/3": then it writes that TUM Kinect's over it, and the export warns when
//             that camera is not the dataset's.
//   orbslam2  ORB-SLAM2's Examples/RGB-D/rgbd_tum <vocabulary> <settings> <dir> <associations>:
//               rgb/<t>.png, depth/<t>.png             links under each image's own stamp
//               associations.txt                       "t_rgb rgb/<t>.png t_depth depth/<t>.png"
//                                                       (associate.py's lines, no comments:
//                                                       rgbd_tum reads every line as a frame)
//               orbslam2_settings.yaml                 the dataset's intrinsics (orbslam2_settings)
//               groundtruth.txt                        link to the dataset's
//   euroc     the EuRoC MAV / ASL layout with depth and the IMU (euroc_export.hpp)
//   kapture   a Kapture 1.1 folder with Wi-Fi and IMU records (kapture_export.hpp)
//   rosbag    one ROS 1 bag with the TUM bags' topics, the IMU, odometry and Wi-Fi
//             (rosbag_export.hpp)
//   all       export.json                            what was exported, the TUM camera match,
//                                                       warnings, and how to run the peer
//
// Stamps are written as TUM writes them (6 decimals, or 9 when finer), so each name is exactly
// the frame's time. The folder is written atomically and follows core/output_folder.hpp.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/camera_intrinsics.hpp"
#include "core/timestamp.hpp"
#include "interop/tum_camera.hpp"

namespace wifislam::interop {

enum class Peer { kRtabmap, kOrbslam2, kEuroc, kKapture, kRosbag };
const char* to_string(Peer peer);
std::optional<Peer> peer_from_string(std::string_view name);
/// Every peer's name, as --for takes it.
std::vector<std::string> peer_names();

inline constexpr const char* kRtabmapRgbDir = "rgb_sync";
inline constexpr const char* kRtabmapDepthDir = "depth_sync";
inline constexpr const char* kOrbslam2Settings = "orbslam2_settings.yaml";
inline constexpr const char* kExportJson = "export.json";
inline constexpr const char* kExportFormatName = "wifislam-export";
inline constexpr int kExportFormatVersion = 1;

struct PeerExportOptions {
  Peer peer = Peer::kRtabmap;
  /// Check the dataset's files against manifest.json first (off = --no-verify, as for `slam`).
  bool verify_checksums = true;
  /// Replace an existing output folder (the caller has applied check_output_folder).
  bool overwrite = false;
};

struct PeerExportSummary {
  std::filesystem::path dataset, output;
  Peer peer = Peer::kRtabmap;
  std::int64_t frames = 0;
  Timestamp first_time, last_time;  // rgb stamps of the first and last exported frame
  CameraIntrinsics intrinsics;
  /// The TUM Kinect whose intrinsics the dataset's calibration equals, if any.
  std::optional<TumCamera> tum_camera;
  /// Said as "warning: ..." on stderr; the export is complete anyway.
  std::vector<std::string> warnings;
  /// The peer's command line for this export.
  std::string run_command;
  std::string full_report() const;
};

/// Exports `dataset` (ours or a plain TUM RGB-D folder with images) into `output`. Throws
/// InvalidInputError (exit 2) before anything is written for a dataset without images, frames
/// sharing a stamp (names would clash), or, for rtabmap, a stamp that is not a positive time
/// (rtabmap-rgbd_dataset rejects "0.000000.png" and with it the sequence: datasets generated
/// before the time origin start at 0); the dataset reader's IoError / ParseError pass through.
PeerExportSummary export_for_peer(const std::filesystem::path& dataset,
                                  const std::filesystem::path& output,
                                  const PeerExportOptions& options);

}  // namespace wifislam::interop
