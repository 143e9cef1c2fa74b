#include "interop/kapture_export.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/atomic_file.hpp"
#include "core/dataset_format.hpp"
#include "core/dataset_reader.hpp"
#include "core/error.hpp"
#include "core/stop_signal.hpp"
#include "core/text_lines.hpp"
#include "core/wifi_csv.hpp"
#include "interop/relative_link.hpp"

namespace wifislam::interop {

namespace fs = std::filesystem;

namespace {

constexpr const char* kKaptureVersionLine = "# kapture format: 1.1\n";
constexpr const char* kRig = "robot";

std::string us(Timestamp t) { return std::to_string(t.ns / 1000); }

/// "qw, qx, qy, qz, tx, ty, tz" of a transform.
std::string kapture_pose(const Pose& pose) {
  const Eigen::Quaterniond q(pose.linear());
  const Eigen::Vector3d& t = pose.translation();
  std::string out;
  for (double v : {q.w(), q.x(), q.y(), q.z(), t.x(), t.y(), t.z()})
    out += (out.empty() ? "" : ", ") + format_double_exact(v + 0.0);  // no "-0"
  return out;
}

std::string kapture_file(const char* columns, const std::string& rows) {
  return std::string(kKaptureVersionLine) + "# " + columns + "\n" + rows;
}

/// A Kapture .depth file: the depth map's float32 metres, row-major, little-endian.
void write_depth_file(const fs::path& png, const fs::path& out, const DatasetCalibration& c) {
  std::ifstream in(png, std::ios::binary);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) throw IoError(png.string() + ": cannot be read");
  const cv::Mat depth_m = decode_depth_png(bytes, c.depth_units_per_metre, png.string());
  // sensors.txt gives the size; a .depth file of another size would be read as garbage.
  check_image_size(depth_m, c.intrinsics, png.string());
  static_assert(std::endian::native == std::endian::little, "Kapture's .depth is little-endian");
  std::string raw(depth_m.total() * sizeof(float), '\0');
  for (int r = 0; r < depth_m.rows; ++r) {
    std::memcpy(raw.data() + static_cast<std::size_t>(r) * depth_m.cols * sizeof(float),
                depth_m.ptr<float>(r), depth_m.cols * sizeof(float));
  }
  write_file_atomic(out, raw);
}

}  // namespace

KaptureInput read_kapture_input(const fs::path& dataset, std::vector<FramePair> pairs,
                                const DatasetCalibration& calibration) {
  if (!fs::exists(dataset / dataset::kGroundTruth)) {
    throw InvalidInputError(dataset.string() +
                            ": has no groundtruth.txt, which Kapture's trajectories.txt needs");
  }
  for (const FramePair& p : pairs) {
    if (p.rgb_time.ns < 0 || p.depth_time.ns < 0) {
      throw InvalidInputError(
          fmt::format("{}: frame time {} is negative; Kapture's timestamps are unsigned",
                      dataset.string(), p.rgb_time.to_tum_string()));
    }
  }
  KaptureInput input;
  input.pairs = std::move(pairs);
  input.calibration = calibration;
  input.ground_truth = read_ground_truth(dataset);
  if (fs::exists(dataset / dataset::kWifi))
    input.scans = read_wifi_csv((dataset / dataset::kWifi).string());
  // Each receiver becomes a Kapture sensor named by its sensor_id: not another sensor's name, and
  // not a comment line of Kapture's text files.
  for (const WifiScan& scan : input.scans) {
    const std::string& id = scan.sensor_id;
    if (id == "cam0" || id == "depth0" || id == "accel0" || id == "gyro0" || id.starts_with('#')) {
      throw InvalidInputError(
          fmt::format("{}: sensor_id '{}' cannot name a Kapture Wi-Fi sensor ({})",
                      (dataset / dataset::kWifi).string(), id,
                      id.starts_with('#') ? "a '#' starts a comment in Kapture's files"
                                          : "the export names its camera, depth or IMU sensor so"));
    }
  }
  if (calibration.imu && fs::exists(dataset / dataset::kImu))
    input.imu = read_imu_csv((dataset / dataset::kImu).string());
  return input;
}

void write_kapture(const fs::path& dataset, const KaptureInput& input, const fs::path& final_path,
                   const fs::path& staging) {
  const fs::path sensors = staging / "sensors";
  const fs::path data = sensors / "records_data";
  fs::create_directories(data / "rgb");
  fs::create_directories(data / "depth");
  const DatasetCalibration& c = input.calibration;
  const CameraIntrinsics& k = c.intrinsics;
  const bool imu = !input.imu.empty();
  // One Kapture Wi-Fi sensor per receiver of wifi.csv (its sensor_id), in order of first scan:
  // two receivers' scans at one instant are two records, not one overwriting the other.
  // `generate` writes one receiver, wifi0, which is declared even for a dataset without scans.
  std::vector<std::string> wifi_sensors;
  for (const WifiScan& scan : input.scans) {
    if (std::find(wifi_sensors.begin(), wifi_sensors.end(), scan.sensor_id) == wifi_sensors.end())
      wifi_sensors.push_back(scan.sensor_id);
  }
  if (wifi_sensors.empty()) wifi_sensors.push_back("wifi0");

  const std::string pinhole = fmt::format(
      "PINHOLE, {}, {}, {}, {}, {}, {}", k.width_px, k.height_px, format_double_exact(k.fx_px),
      format_double_exact(k.fy_px), format_double_exact(k.cx_px), format_double_exact(k.cy_px));
  std::string sensor_rows = fmt::format("cam0, rgb, camera, {}\n", pinhole);
  sensor_rows += fmt::format("depth0, depth, depth, {}\n", pinhole);
  for (const std::string& sensor : wifi_sensors) sensor_rows += sensor + ", wifi, wifi\n";
  if (imu) sensor_rows += "accel0, imu, accelerometer\ngyro0, imu, gyroscope\n";
  write_file_atomic(
      sensors / "sensors.txt",
      kapture_file("sensor_device_id, name, sensor_type, [sensor_params]+", sensor_rows));

  // The rig is the camera's optical frame; a rig line is the transform from rig to sensor.
  const std::string identity = kapture_pose(Pose::Identity());
  std::string rig_rows;
  for (const char* sensor : {"cam0", "depth0"})
    rig_rows += fmt::format("{}, {}, {}\n", kRig, sensor, identity);
  for (const std::string& sensor : wifi_sensors)
    rig_rows += fmt::format("{}, {}, {}\n", kRig, sensor, identity);
  if (imu) {
    const std::string imu_from_camera = kapture_pose(c.camera_from_imu().inverse());
    for (const char* sensor : {"accel0", "gyro0"})
      rig_rows += fmt::format("{}, {}, {}\n", kRig, sensor, imu_from_camera);
  }
  write_file_atomic(
      sensors / "rigs.txt",
      kapture_file("rig_device_id, sensor_device_id, qw, qx, qy, qz, tx, ty, tz", rig_rows));

  std::string trajectory_rows;
  for (const StampedPose& p : input.ground_truth)
    trajectory_rows +=
        fmt::format("{}, {}, {}\n", us(p.time), kRig, kapture_pose(p.pose().inverse()));
  write_file_atomic(
      sensors / "trajectories.txt",
      kapture_file("timestamp, device_id, qw, qx, qy, qz, tx, ty, tz", trajectory_rows));

  std::string camera_rows, depth_rows;
  for (const FramePair& p : input.pairs) {
    throw_if_stop_requested();  // `export`: Ctrl-C removes the unfinished folder
    const std::string rgb = "rgb/" + us(p.rgb_time) + ".png";
    const std::string depth = "depth/" + us(p.rgb_time) + ".depth";
    link_relative(dataset / p.rgb_path, final_path / "sensors/records_data" / rgb, data / rgb);
    write_depth_file(dataset / p.depth_path, data / depth, c);
    camera_rows += fmt::format("{}, cam0, {}\n", us(p.rgb_time), rgb);
    depth_rows += fmt::format("{}, depth0, {}\n", us(p.rgb_time), depth);
  }
  write_file_atomic(sensors / "records_camera.txt",
                    kapture_file("timestamp, device_id, image_path", camera_rows));
  write_file_atomic(sensors / "records_depth.txt",
                    kapture_file("timestamp, device_id, depth_map_path", depth_rows));

  std::string wifi_rows;
  for (const WifiScan& scan : input.scans) {
    for (const WifiReading& r : scan.readings) {
      wifi_rows += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}\n", us(scan.time), scan.sensor_id,
                               r.bssid.to_string(), r.frequency_khz / 1000, r.rssi_dbm, r.ssid,
                               us(scan.start_time), us(scan.end_time));
    }
  }
  write_file_atomic(sensors / "records_wifi.txt",
                    kapture_file("timestamp, device_id, BSSID, frequency, RSSI, SSID, "
                                 "scan_time_start, scan_time_end",
                                 wifi_rows));
  if (!imu) return;
  std::string accel_rows, gyro_rows;
  for (const ImuReading& r : input.imu) {
    const Eigen::Vector3d& a = r.specific_force_mps2;
    const Eigen::Vector3d& w = r.angular_velocity_radps;
    accel_rows += fmt::format("{}, accel0, {}, {}, {}\n", us(r.time), format_double_exact(a.x()),
                              format_double_exact(a.y()), format_double_exact(a.z()));
    gyro_rows += fmt::format("{}, gyro0, {}, {}, {}\n", us(r.time), format_double_exact(w.x()),
                             format_double_exact(w.y()), format_double_exact(w.z()));
  }
  write_file_atomic(sensors / "records_accelerometer.txt",
                    kapture_file("timestamp, device_id, x_acc, y_acc, z_acc", accel_rows));
  write_file_atomic(sensors / "records_gyroscope.txt",
                    kapture_file("timestamp, device_id, x_speed, y_speed, z_speed", gyro_rows));
}

}  // namespace wifislam::interop
