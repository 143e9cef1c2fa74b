#pragma once
// A dataset as a Kapture folder (kapture data format 1.1, NAVER LABS; LaMAR's Wi-Fi records), for
// visual localisation and radio-fingerprint tools that read it:
//
//   sensors/sensors.txt            cam0 (PINHOLE w h fx fy cx cy), depth0 (the same, type depth),
//                                  wifi0 (wifi), and with an IMU accel0 (accelerometer) and gyro0
//                                  (gyroscope)
//   sensors/rigs.txt               rig "robot" = the camera's optical frame: cam0, depth0 and wifi0
//                                  at its origin (the antenna is at the camera), the IMU at
//                                  T_imu_cam
//   sensors/trajectories.txt       the rig at every frame: world -> rig (Kapture's and COLMAP's
//                                  convention), from groundtruth.txt
//   sensors/records_camera.txt     records_data/rgb/<us>.png, links to the dataset's images
//   sensors/records_depth.txt      records_data/depth/<us>.depth, float32 metres, little-endian,
//                                  row-major, 0 = no reading (converted from the depth PNGs)
//   sensors/records_wifi.txt       timestamp, device_id, BSSID, frequency, RSSI, SSID,
//                                  scan_time_start, scan_time_end: one row per BSSID heard
//   sensors/records_accelerometer.txt, records_gyroscope.txt   imu.csv's samples
//
// Every file starts with "# kapture format: 1.1" and a comment naming its columns. Timestamps are
// integer microseconds (Unix time, as LaMAR's). Wi-Fi frequencies are in MHz: the format's text
// says Hz, but its own example and LaMAR's data write MHz (2400, 2412, ...).

#include <filesystem>
#include <optional>
#include <vector>

#include "core/dataset_calibration.hpp"
#include "core/imu_csv.hpp"
#include "core/tum_file_list.hpp"
#include "core/tum_trajectory.hpp"
#include "core/wifi_scan.hpp"

namespace wifislam::interop {

struct KaptureInput {
  std::vector<FramePair> pairs;
  DatasetCalibration calibration;
  Trajectory ground_truth;  // camera to world at the frame times
  std::vector<WifiScan> scans;
  std::vector<ImuReading> imu;  // empty without an IMU
};

/// Reads what the folder is made of. Throws InvalidInputError (exit 2) for a dataset without
/// ground truth (Kapture's trajectories are the poses) or with a negative stamp.
KaptureInput read_kapture_input(const std::filesystem::path& dataset, std::vector<FramePair> pairs,
                                const DatasetCalibration& calibration);

/// Writes the folder into `staging` (links relative to `final_path`, where it will live).
void write_kapture(const std::filesystem::path& dataset, const KaptureInput& input,
                   const std::filesystem::path& final_path, const std::filesystem::path& staging);

}  // namespace wifislam::interop
