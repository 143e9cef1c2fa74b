#pragma once
// The dataset folder: TUM RGB-D compatible, so RTAB-Map, ORB-SLAM and
// evo read it, plus Wi-Fi, odometry, calibration and a manifest. The names and conventions both
// the writer (sim/generate) and the reader (dataset_reader.hpp) use.
//
//   rgb/<t>.png  depth/<t>.png   colour (8-bit BGR PNG) and depth (16-bit PNG, 5000 = 1 m,
//                                0 = no reading); <t> is the frame time with 6 decimals
//
// Times are Unix seconds, as real sensors stamp them (TUM: "seconds since the Unix epoch"): a
// generated dataset's route starts at the scene's sensors.time_origin_s, by default
// kDefaultTimeOriginS. Readers take any origin (datasets written before it start at 0).
//
//   rgb.txt  depth.txt           "timestamp filename" per frame (TUM)
//   associations.txt             "t_rgb rgb/<t>.png t_depth depth/<t>.png" (TUM associate.py)
//   groundtruth.txt              camera-to-world poses at the frame times (TUM trajectory)
//   odometry.txt                 wheel odometry: robot base in the odometry frame (TUM trajectory)
//   wifi.csv                     one row per BSSID heard per scan (wifi_csv.hpp)
//   imu.csv                      IMU samples (imu_csv.hpp), when the scene has an IMU
//   imu_groundtruth.csv          the IMU's true state at the frame times (imu_groundtruth_csv.hpp)
//   access_points.csv            ground-truth AP positions, power and BSSIDs (studies only)
//   calibration.yaml             intrinsics, depth scale, camera mount, sensor model parameters
//   scene.yaml                   the resolved scene, seed included
//   images.sha256                SHA-256 of every PNG, `sha256sum -c` format
//   manifest.json                versions, parameters, counts, SHA-256 of every other file

#include <cstdint>
#include <string>

#include "core/timestamp.hpp"

namespace wifislam::dataset {

inline constexpr int kFormatVersion = 1;
inline constexpr const char* kFormatName = "wifislam-dataset";

inline constexpr const char* kRgbDir = "rgb";
inline constexpr const char* kDepthDir = "depth";
inline constexpr const char* kRgbList = "rgb.txt";
inline constexpr const char* kDepthList = "depth.txt";
inline constexpr const char* kAssociations = "associations.txt";
inline constexpr const char* kGroundTruth = "groundtruth.txt";
inline constexpr const char* kOdometry = "odometry.txt";
inline constexpr const char* kWifi = "wifi.csv";
inline constexpr const char* kImu = "imu.csv";
inline constexpr const char* kImuGroundTruth = "imu_groundtruth.csv";
inline constexpr const char* kAccessPoints = "access_points.csv";
inline constexpr const char* kCalibration = "calibration.yaml";
inline constexpr const char* kScene = "scene.yaml";
inline constexpr const char* kImageChecksums = "images.sha256";
inline constexpr const char* kManifest = "manifest.json";

/// Where generated datasets' clocks start: 1700000000 s = 2023-11-14 22:13:20 UTC. A whole
/// number of seconds, so adding it keeps every time exact (frame times are whole microseconds),
/// and a recent Unix time, so peers that read times from file names (RTAB-Map's
/// rtabmap-rgbd_dataset refuses a frame named 0.000000.png) or expect Unix stamps take them.
inline constexpr std::uint64_t kDefaultTimeOriginS = 1'700'000'000;
/// The latest origin a scene may set: 2100-01-01 00:00:00 UTC, far from where 64-bit nanoseconds
/// end (2262) whatever the route's length.
inline constexpr std::uint64_t kMaxTimeOriginS = 4'102'444'800;

/// TUM depth PNGs: 5000 units per metre (TUM RGB-D benchmark, "File Formats").
inline constexpr double kDepthUnitsPerMetre = 5000.0;
/// TUM associate.py pairs rgb and depth stamps closer than this (its --max_difference default).
inline constexpr double kAssociationMaxDifferenceS = 0.02;

/// "rgb/1.033333.png" style relative path of a frame image.
inline std::string frame_image_path(const char* dir, Timestamp t) {
  return std::string(dir) + "/" + t.to_string(6) + ".png";
}

}  // namespace wifislam::dataset
