#include "interop/rosbag_export.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "core/dataset_format.hpp"
#include "core/dataset_reader.hpp"
#include "core/error.hpp"
#include "core/imu_csv.hpp"
#include "core/stop_signal.hpp"
#include "core/tum_trajectory.hpp"
#include "core/wifi_csv.hpp"
#include "interop/rosbag/rosbag_writer.hpp"

namespace wifislam::interop {

namespace fs = std::filesystem;

namespace {

constexpr const char* kCameraFrame = "openni_rgb_optical_frame";
constexpr const char* kGroundTruthFrame = "kinect";
constexpr const char* kImuFrame = "imu_link";

bag::RigidTransform rigid(const Pose& pose) {
  const Eigen::Quaterniond q(pose.linear());
  const Eigen::Vector3d& t = pose.translation();
  return {{t.x(), t.y(), t.z()}, {q.x(), q.y(), q.z(), q.w()}};
}

/// The latest time ROS 1 holds: unsigned 32-bit seconds.
constexpr std::int64_t kMaxRosTimeNs = 0xFFFFFFFFLL * 1'000'000'000;

/// The topic of one receiver's scans: /wifi/scan for wifi0, the receiver `generate` writes,
/// and /wifi/<sensor_id>/scan for any other (wifi.csv's sensor_id), so that the scans of two
/// receivers stay apart. An id that is no ROS name ([A-Za-z][A-Za-z0-9_]*) is refused.
std::string wifi_topic(const std::string& sensor_id) {
  if (sensor_id == "wifi0") return "/wifi/scan";
  const bool ros_name = !sensor_id.empty() &&
                        std::isalpha(static_cast<unsigned char>(sensor_id[0])) &&
                        std::all_of(sensor_id.begin(), sensor_id.end(), [](char ch) {
                          return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
                        });
  if (!ros_name) {
    throw InvalidInputError(fmt::format(
        "wifi.csv: sensor_id '{}' cannot name a ROS topic (/wifi/<sensor_id>/scan): a ROS name "
        "is a letter followed by letters, digits and underscores",
        sensor_id));
  }
  return "/wifi/" + sensor_id + "/scan";
}

class BagExport {
 public:
  BagExport(const fs::path& dataset, const DatasetCalibration& calibration, const fs::path& staging,
            bool verify_checksums)
      : dataset_(dataset),
        calibration_(calibration),
        writer_((staging / kBagFile).string(), bag::Compression::kLz4) {
    DatasetReaderOptions options;
    options.verify_checksums = verify_checksums;
    reader_.emplace(dataset, options);
    ground_truth_ = read_ground_truth(dataset, verify_checksums);
    if (calibration.imu && fs::exists(dataset / dataset::kImu))
      imu_ = read_imu_csv((dataset / dataset::kImu).string());
    const CameraIntrinsics& k = calibration.intrinsics;
    camera_ = {k.width_px, k.height_px, k.fx_px, k.fy_px, k.cx_px, k.cy_px};
  }

  std::int64_t write() {
    // The stream's events in time order, with the IMU samples merged in by time.
    std::size_t next_imu = 0;
    while (auto event = reader_->next()) {
      throw_if_stop_requested();  // `export`: Ctrl-C removes the unfinished bag
      const Timestamp t = event_time(*event);
      for (; next_imu < imu_.size() && imu_[next_imu].time <= t; ++next_imu)
        write_imu(imu_[next_imu]);
      if (!static_written_) write_static(t);
      if (auto* frame = std::get_if<RgbdFrame>(&*event)) {
        write_frame(*frame);
      } else if (auto* scan = std::get_if<WifiScan>(&*event)) {
        write_scan(*scan);
      } else {
        write_odometry(std::get<OdometryReading>(*event));
      }
    }
    for (; next_imu < imu_.size(); ++next_imu) write_imu(imu_[next_imu]);
    writer_.close();
    return messages_;
  }

 private:
  void write_static(Timestamp t) {
    std::vector<bag::FrameTransform> fixed = {
        {t.ns, "base_link", kCameraFrame, rigid(calibration_.camera_in_base)}};
    if (calibration_.imu)
      fixed.push_back({t.ns, "base_link", kImuFrame, rigid(calibration_.imu->imu_in_base)});
    writer_.transforms("/tf_static", t.ns, fixed, bag::Latched::kYes);
    ++messages_;
    static_written_ = true;
  }

  void write_frame(const RgbdFrame& frame) {
    const std::int64_t ns = frame.time.ns;
    cv::Mat rgb;
    cv::cvtColor(frame.rgb, rgb, cv::COLOR_BGR2RGB);
    writer_.image("/camera/rgb/image_color", ns, kCameraFrame, rgb.cols, rgb.rows, "rgb8",
                  static_cast<std::uint32_t>(rgb.step), rgb.data, rgb.total() * rgb.elemSize());
    cv::Mat depth = frame.depth_m.clone();
    depth.setTo(std::numeric_limits<float>::quiet_NaN(), depth == 0.0f);
    writer_.image("/camera/depth/image", ns, kCameraFrame, depth.cols, depth.rows, "32FC1",
                  static_cast<std::uint32_t>(depth.step), depth.data,
                  depth.total() * depth.elemSize());
    writer_.camera_info("/camera/rgb/camera_info", ns, kCameraFrame, camera_);
    writer_.camera_info("/camera/depth/camera_info", ns, kCameraFrame, camera_);
    messages_ += 4;
    // The ground truth at the frame's time (groundtruth.txt holds one pose per frame).
    while (next_truth_ < ground_truth_.size() && ground_truth_[next_truth_].time < frame.time)
      ++next_truth_;
    if (next_truth_ < ground_truth_.size() && ground_truth_[next_truth_].time == frame.time) {
      const bag::RigidTransform pose = rigid(ground_truth_[next_truth_].pose());
      writer_.transforms("/tf", ns, {{ns, "world", kGroundTruthFrame, pose}});
      writer_.pose("/ground_truth/pose", ns, "world", pose);
      messages_ += 2;
    }
  }

  void write_scan(const WifiScan& scan) {
    std::vector<bag::WifiEntry> entries;
    for (const WifiReading& r : scan.readings) {
      entries.push_back({r.bssid.to_string(), r.ssid,
                         static_cast<std::uint32_t>(r.frequency_khz / 1000),
                         static_cast<std::int16_t>(r.rssi_dbm)});
    }
    writer_.wifi_scan(wifi_topic(scan.sensor_id), scan.time.ns, kCameraFrame, scan.start_time.ns,
                      scan.end_time.ns, entries);
    ++messages_;
  }

  void write_odometry(const OdometryReading& reading) {
    const bag::RigidTransform pose = rigid(reading.base_in_odom);
    writer_.odometry("/odom", reading.time.ns, "odom", "base_link", pose,
                     twist_since(previous_odometry_, reading));
    previous_odometry_ = reading;
    writer_.transforms("/tf", reading.time.ns, {{reading.time.ns, "odom", "base_link", pose}});
    messages_ += 2;
  }

  /// The base's velocity in its own frame over the interval since the previous reading (as a
  /// wheel-odometry driver derives its twist from the encoder ticks of that interval); zero for
  /// the first reading, which has none before it.
  static bag::Twist twist_since(const std::optional<OdometryReading>& previous,
                                const OdometryReading& reading) {
    bag::Twist twist;
    if (!previous || reading.time.ns <= previous->time.ns) return twist;
    const double dt_s = static_cast<double>(reading.time.ns - previous->time.ns) * 1e-9;
    const Pose& from = previous->base_in_odom;
    const Pose& to = reading.base_in_odom;
    const Eigen::Vector3d v =
        to.linear().transpose() * (to.translation() - from.translation()) / dt_s;
    // The relative rotation's axis is the same in both frames, so this is the angular velocity
    // in the base frame.
    const Eigen::AngleAxisd turn(from.linear().transpose() * to.linear());
    const Eigen::Vector3d w = turn.axis() * turn.angle() / dt_s;
    twist.linear_mps = {v.x(), v.y(), v.z()};
    twist.angular_radps = {w.x(), w.y(), w.z()};
    return twist;
  }

  void write_imu(const ImuReading& r) {
    const ImuCalibration& c = *calibration_.imu;
    // Discrete white-noise variance of one sample: density^2 x rate (Kalibr's convention).
    const double gyro_var = c.gyroscope_noise_density * c.gyroscope_noise_density * c.rate_hz;
    const double accel_var =
        c.accelerometer_noise_density * c.accelerometer_noise_density * c.rate_hz;
    const Eigen::Vector3d& w = r.angular_velocity_radps;
    const Eigen::Vector3d& a = r.specific_force_mps2;
    writer_.imu("/imu", r.time.ns, kImuFrame, {w.x(), w.y(), w.z()}, {a.x(), a.y(), a.z()},
                gyro_var, accel_var);
    ++messages_;
  }

  fs::path dataset_;
  DatasetCalibration calibration_;
  bag::BagWriter writer_;
  std::optional<DatasetReader> reader_;
  Trajectory ground_truth_;
  std::size_t next_truth_ = 0;
  std::vector<ImuReading> imu_;
  bag::PinholeCamera camera_;
  bool static_written_ = false;
  std::optional<OdometryReading> previous_odometry_;
  std::int64_t messages_ = 0;
};

}  // namespace

void check_rosbag_input(const fs::path& dataset) {
  if (!fs::exists(dataset / dataset::kGroundTruth)) {
    throw InvalidInputError(dataset.string() +
                            ": has no groundtruth.txt, which the bag's ground-truth topic needs");
  }
  // A bag holds no message at time 0 (ros::TIME_MIN is 1 ns) and none after 2106. Every record
  // of a generated dataset lies within its frames' times.
  const Trajectory truth = read_ground_truth(dataset, false);
  for (const StampedPose& p : truth) {
    if (p.time.ns <= 0) {
      throw InvalidInputError(fmt::format(
          "{}: time {} is not a positive time, which a ROS bag cannot hold. This dataset starts "
          "at 0 s (generated before datasets had a time origin, or with sensors.time_origin_s: "
          "0): generate it again with a time origin (by default {} s)",
          dataset.string(), p.time.to_tum_string(), dataset::kDefaultTimeOriginS));
    }
    if (p.time.ns > kMaxRosTimeNs) {
      throw InvalidInputError(fmt::format("{}: time {} is after 2106, the last time ROS 1 holds",
                                          dataset.string(), p.time.to_tum_string()));
    }
  }
  // Every receiver needs a topic: checked before the bag is begun.
  if (fs::exists(dataset / dataset::kWifi)) {
    for (const WifiScan& scan : read_wifi_csv((dataset / dataset::kWifi).string()))
      wifi_topic(scan.sensor_id);
  }
}

std::int64_t write_rosbag(const fs::path& dataset, const DatasetCalibration& calibration,
                          const fs::path& staging, bool verify_checksums) {
  try {
    return BagExport(dataset, calibration, staging, verify_checksums).write();
  } catch (const std::runtime_error& e) {
    // librosbag's own errors (a full disk, a time outside ROS time) as ours.
    if (dynamic_cast<const Error*>(&e) != nullptr) throw;
    throw IoError(fmt::format("{}: {}", (staging / kBagFile).string(), e.what()));
  }
}

}  // namespace wifislam::interop
