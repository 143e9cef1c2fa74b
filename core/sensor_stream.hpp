#pragma once
// What a SLAM system receives: a time-ordered stream of RGB-D frames, Wi-Fi scans and wheel
// odometry readings. Two sources implement it: the dataset reader (a folder on disk, ours or a
// plain TUM RGB-D one) and the generator's in-memory stream (no disk at all). SLAM code reads
// only this interface, never ground truth or simulator internals.

#include <optional>
#include <string>
#include <variant>

#include <opencv2/core/mat.hpp>

#include "core/camera_intrinsics.hpp"
#include "core/pose.hpp"
#include "core/timestamp.hpp"
#include "core/wifi_scan.hpp"

namespace wifislam {

struct RgbdFrame {
  Timestamp time;
  std::int64_t index = 0;            // 0-based position in the stream's frame sequence
  cv::Mat rgb;                       // CV_8UC3, BGR channel order (OpenCV's convention)
  cv::Mat depth_m;                   // CV_32FC1, metres along the optical axis, 0 = no reading
  std::string rgb_path, depth_path;  // relative to the dataset folder; empty when streamed
};

/// Wheel odometry: pose of the robot base in the odometry frame (drifts over time).
struct OdometryReading {
  Timestamp time;
  Pose base_in_odom = Pose::Identity();
};

using SensorEvent = std::variant<RgbdFrame, WifiScan, OdometryReading>;

/// Time of any event.
Timestamp event_time(const SensorEvent& event);

class SensorStream {
 public:
  virtual ~SensorStream() = default;
  /// The next event in time order (ties: odometry, then Wi-Fi, then the frame), or nullopt at
  /// the end. Frames come with images loaded.
  virtual std::optional<SensorEvent> next() = 0;
  virtual const CameraIntrinsics& intrinsics() const = 0;
  /// Camera pose in the robot base frame (for fusing odometry); identity when unknown.
  virtual Pose camera_in_base() const { return Pose::Identity(); }
  virtual bool has_wifi() const = 0;
  virtual bool has_odometry() const = 0;
  /// A short description for logs ("dataset /data/c_hall (24000 frames)").
  virtual std::string description() const = 0;
};

}  // namespace wifislam
