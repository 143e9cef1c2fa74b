#pragma once
// Writing a ROS 1 bag with Debian's librosbag_storage and the ROS message packages. ROS 1's
// message headers need C++17 (they name std::allocator<void>::rebind, gone in C++20), so this is
// its own small library built as C++17, and its interface holds standard types only.
//
// Every message's stamp is its header stamp, and header.seq numbers a topic's messages from 0 as a
// ROS publisher does; times are Unix nanoseconds (ROS time: whole seconds
// and nanoseconds, to 2106). Wi-Fi scans are wifislam_msgs/WifiScan (WifiScan.msg beside this
// file), whose definition travels in the bag as every message type's does, so any reader of ROS
// bags decodes it without our sources.

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace wifislam::interop::bag {

enum class Compression { kNone, kLz4, kBz2 };

struct RigidTransform {
  std::array<double, 3> translation_m{0.0, 0.0, 0.0};
  std::array<double, 4> rotation_xyzw{0.0, 0.0, 0.0, 1.0};
};

struct FrameTransform {
  std::int64_t time_ns = 0;
  std::string parent, child;
  RigidTransform transform;  // the child frame in the parent frame
};

/// Velocities of a frame, in that frame (nav_msgs/Odometry's twist, in its child frame).
struct Twist {
  std::array<double, 3> linear_mps{0.0, 0.0, 0.0};
  std::array<double, 3> angular_radps{0.0, 0.0, 0.0};
};

/// A latched topic (tf2's /tf_static): `rosbag play` re-advertises it latched.
enum class Latched { kNo, kYes };

struct PinholeCamera {
  int width_px = 0, height_px = 0;
  double fx_px = 0, fy_px = 0, cx_px = 0, cy_px = 0;
};

struct WifiEntry {
  std::string bssid, ssid;
  std::uint32_t frequency_mhz = 0;
  std::int16_t rssi_dbm = 0;
};

class BagWriter {
 public:
  /// Opens `path` for writing (replacing it). Throws std::runtime_error with librosbag's message.
  BagWriter(const std::string& path, Compression compression);
  ~BagWriter();
  BagWriter(const BagWriter&) = delete;
  BagWriter& operator=(const BagWriter&) = delete;

  /// sensor_msgs/Image: `data` holds height rows of `step` bytes.
  void image(const std::string& topic, std::int64_t time_ns, const std::string& frame_id, int width,
             int height, const std::string& encoding, std::uint32_t step, const std::uint8_t* data,
             std::size_t bytes);
  /// sensor_msgs/CameraInfo of an undistorted pinhole camera (plumb_bob, zero coefficients).
  void camera_info(const std::string& topic, std::int64_t time_ns, const std::string& frame_id,
                   const PinholeCamera& camera);
  /// tf2_msgs/TFMessage (on /tf, or /tf_static latched).
  void transforms(const std::string& topic, std::int64_t time_ns,
                  const std::vector<FrameTransform>& transforms, Latched latched = Latched::kNo);
  /// sensor_msgs/Imu without orientation (orientation_covariance[0] = -1, as REP 145 says), with
  /// diagonal covariances of the angular velocity and linear acceleration.
  void imu(const std::string& topic, std::int64_t time_ns, const std::string& frame_id,
           const std::array<double, 3>& angular_velocity_radps,
           const std::array<double, 3>& linear_acceleration_mps2, double gyro_variance,
           double accel_variance);
  /// nav_msgs/Odometry: `child_frame` in `frame_id`, with its twist; covariances zero (not
  /// known).
  void odometry(const std::string& topic, std::int64_t time_ns, const std::string& frame_id,
                const std::string& child_frame, const RigidTransform& pose, const Twist& twist);
  /// geometry_msgs/PoseStamped.
  void pose(const std::string& topic, std::int64_t time_ns, const std::string& frame_id,
            const RigidTransform& pose);
  /// wifislam_msgs/WifiScan.
  void wifi_scan(const std::string& topic, std::int64_t time_ns, const std::string& frame_id,
                 std::int64_t scan_start_ns, std::int64_t scan_end_ns,
                 const std::vector<WifiEntry>& entries);
  /// Writes the index and closes the file; throws std::runtime_error on failure.
  void close();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace wifislam::interop::bag
