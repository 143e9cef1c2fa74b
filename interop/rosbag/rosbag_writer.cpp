// Built as C++17 (see rosbag_writer.hpp). The message types are Debian's ROS 1 packages; the one
// type of our own, wifislam_msgs/WifiScan, is declared here the way genmsg's generated headers
// declare a type: its fields, its serializer, its data type, MD5 sum and full definition.
#include "interop/rosbag/rosbag_writer.hpp"

#include <map>
#include <stdexcept>

#include <boost/make_shared.hpp>

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/serialization.h>
#include <rosbag/bag.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/Imu.h>
#include <std_msgs/Header.h>
#include <tf2_msgs/TFMessage.h>

namespace wifislam_msgs {

struct WifiScan {
  std_msgs::Header header;
  ros::Time scan_start;
  ros::Time scan_end;
  std::vector<std::string> bssid;
  std::vector<std::uint32_t> frequency_mhz;
  std::vector<std::int16_t> rssi_dbm;
  std::vector<std::string> ssid;
};

}  // namespace wifislam_msgs

namespace ros {
namespace message_traits {

// MD5 of the definition as genmsg computes it (gentools.compute_md5): the test recomputes it from
// the definition stored in the bag.
template <>
struct MD5Sum<wifislam_msgs::WifiScan> {
  static const char* value() { return "e788d55ae1c072f5d570cc7ef1bcb032"; }
  static const char* value(const wifislam_msgs::WifiScan&) { return value(); }
};

template <>
struct DataType<wifislam_msgs::WifiScan> {
  static const char* value() { return "wifislam_msgs/WifiScan"; }
  static const char* value(const wifislam_msgs::WifiScan&) { return value(); }
};

// WifiScan.msg followed by std_msgs/Header's definition, as genmsg's full text has it.
template <>
struct Definition<wifislam_msgs::WifiScan> {
  static const char* value() {
    return "# One Wi-Fi scan (wifislam): every access point heard, as parallel arrays (entry i of "
           "each array\n"
           "# is one BSSID). header.stamp is when the scan reported (the end of its sweep); "
           "scan_start and\n"
           "# scan_end bound the sweep. frequency_mhz is the channel's centre frequency, rssi_dbm "
           "the\n"
           "# received signal strength.\n"
           "Header header\n"
           "time scan_start\n"
           "time scan_end\n"
           "string[] bssid\n"
           "uint32[] frequency_mhz\n"
           "int16[] rssi_dbm\n"
           "string[] ssid\n"
           "\n"
           "================================================================================\n"
           "MSG: std_msgs/Header\n"
           "# Standard metadata for higher-level stamped data types.\n"
           "# This is generally used to communicate timestamped data \n"
           "# in a particular coordinate frame.\n"
           "# \n"
           "# sequence ID: consecutively increasing ID \n"
           "uint32 seq\n"
           "#Two-integer timestamp that is expressed as:\n"
           "# * stamp.sec: seconds (stamp_secs) since epoch (in Python the variable is called "
           "'secs')\n"
           "# * stamp.nsec: nanoseconds since stamp_secs (in Python the variable is called "
           "'nsecs')\n"
           "# time-handling sugar is provided by the client library\n"
           "time stamp\n"
           "#Frame this data is associated with\n"
           "string frame_id\n";
  }
  static const char* value(const wifislam_msgs::WifiScan&) { return value(); }
};

template <>
struct HasHeader<wifislam_msgs::WifiScan> : TrueType {};

}  // namespace message_traits

namespace serialization {

template <>
struct Serializer<wifislam_msgs::WifiScan> {
  template <typename Stream, typename T>
  inline static void allInOne(Stream& stream, T m) {
    stream.next(m.header);
    stream.next(m.scan_start);
    stream.next(m.scan_end);
    stream.next(m.bssid);
    stream.next(m.frequency_mhz);
    stream.next(m.rssi_dbm);
    stream.next(m.ssid);
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};

}  // namespace serialization
}  // namespace ros

namespace wifislam::interop::bag {

namespace {

ros::Time ros_time(std::int64_t ns) {
  if (ns < 0 || ns / 1'000'000'000 > 0xFFFFFFFFLL) {
    throw std::runtime_error("time " + std::to_string(ns) +
                             " ns is outside ROS time (0 to 2106, unsigned seconds)");
  }
  ros::Time t;
  t.sec = static_cast<std::uint32_t>(ns / 1'000'000'000);
  t.nsec = static_cast<std::uint32_t>(ns % 1'000'000'000);
  return t;
}

std_msgs::Header header(std::int64_t ns, const std::string& frame_id) {
  std_msgs::Header h;
  h.stamp = ros_time(ns);
  h.frame_id = frame_id;
  return h;
}

geometry_msgs::Pose pose_msg(const RigidTransform& t) {
  geometry_msgs::Pose p;
  p.position.x = t.translation_m[0];
  p.position.y = t.translation_m[1];
  p.position.z = t.translation_m[2];
  p.orientation.x = t.rotation_xyzw[0];
  p.orientation.y = t.rotation_xyzw[1];
  p.orientation.z = t.rotation_xyzw[2];
  p.orientation.w = t.rotation_xyzw[3];
  return p;
}

}  // namespace

struct BagWriter::Impl {
  rosbag::Bag bag;
  /// Each topic's next header.seq: consecutive from 0, as a ROS publisher numbers its messages.
  std::map<std::string, std::uint32_t> next_seq;
  template <class M>
  void write(const std::string& topic, const M& message, const ros::Time& stamp) {
    bag.write(topic, stamp, message);
  }
  /// A latched topic's connection says so (`latching: 1`), as `rosbag record` stores a latched
  /// publisher's: `rosbag play` then re-advertises it latched, so a node subscribing after the
  /// first message still receives it (tf2's /tf_static is published that way).
  template <class M>
  void write_latched(const std::string& topic, const M& message, const ros::Time& stamp) {
    // librosbag stores a given connection header as it is: it must name the type itself.
    const auto connection = boost::make_shared<ros::M_string>();
    (*connection)["type"] = ros::message_traits::datatype<M>();
    (*connection)["md5sum"] = ros::message_traits::md5sum<M>();
    (*connection)["message_definition"] = ros::message_traits::definition<M>();
    (*connection)["callerid"] = "/wifislam_export";
    (*connection)["latching"] = "1";
    bag.write(topic, stamp, message, connection);
  }
  std_msgs::Header numbered_header(const std::string& topic, std::int64_t ns,
                                   const std::string& frame_id) {
    std_msgs::Header h = header(ns, frame_id);
    h.seq = next_seq[topic]++;
    return h;
  }
};

BagWriter::BagWriter(const std::string& path, Compression compression)
    : impl_(std::make_unique<Impl>()) {
  try {
    impl_->bag.open(path, rosbag::bagmode::Write);
    impl_->bag.setCompression(compression == Compression::kLz4 ? rosbag::compression::LZ4
                              : compression == Compression::kBz2
                                  ? rosbag::compression::BZ2
                                  : rosbag::compression::Uncompressed);
  } catch (const rosbag::BagException& e) {
    throw std::runtime_error(e.what());
  }
}

BagWriter::~BagWriter() {
  try {
    impl_->bag.close();
  } catch (...) {  // a destructor must not throw; close() reports errors
  }
}

void BagWriter::close() {
  try {
    impl_->bag.close();
  } catch (const rosbag::BagException& e) {
    throw std::runtime_error(e.what());
  }
}

void BagWriter::image(const std::string& topic, std::int64_t time_ns, const std::string& frame_id,
                      int width, int height, const std::string& encoding, std::uint32_t step,
                      const std::uint8_t* data, std::size_t bytes) {
  sensor_msgs::Image m;
  m.header = impl_->numbered_header(topic, time_ns, frame_id);
  m.width = static_cast<std::uint32_t>(width);
  m.height = static_cast<std::uint32_t>(height);
  m.encoding = encoding;
  m.is_bigendian = 0;
  m.step = step;
  m.data.assign(data, data + bytes);
  impl_->write(topic, m, m.header.stamp);
}

void BagWriter::camera_info(const std::string& topic, std::int64_t time_ns,
                            const std::string& frame_id, const PinholeCamera& c) {
  sensor_msgs::CameraInfo m;
  m.header = impl_->numbered_header(topic, time_ns, frame_id);
  m.width = static_cast<std::uint32_t>(c.width_px);
  m.height = static_cast<std::uint32_t>(c.height_px);
  m.distortion_model = "plumb_bob";
  m.D = {0.0, 0.0, 0.0, 0.0, 0.0};
  m.K = {c.fx_px, 0.0, c.cx_px, 0.0, c.fy_px, c.cy_px, 0.0, 0.0, 1.0};
  m.R = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  m.P = {c.fx_px, 0.0, c.cx_px, 0.0, 0.0, c.fy_px, c.cy_px, 0.0, 0.0, 0.0, 1.0, 0.0};
  impl_->write(topic, m, m.header.stamp);
}

void BagWriter::transforms(const std::string& topic, std::int64_t time_ns,
                           const std::vector<FrameTransform>& transforms, Latched latched) {
  tf2_msgs::TFMessage m;
  for (const FrameTransform& f : transforms) {
    geometry_msgs::TransformStamped t;
    t.header = header(f.time_ns, f.parent);
    t.child_frame_id = f.child;
    t.transform.translation.x = f.transform.translation_m[0];
    t.transform.translation.y = f.transform.translation_m[1];
    t.transform.translation.z = f.transform.translation_m[2];
    t.transform.rotation.x = f.transform.rotation_xyzw[0];
    t.transform.rotation.y = f.transform.rotation_xyzw[1];
    t.transform.rotation.z = f.transform.rotation_xyzw[2];
    t.transform.rotation.w = f.transform.rotation_xyzw[3];
    m.transforms.push_back(t);
  }
  if (latched == Latched::kYes) {
    impl_->write_latched(topic, m, ros_time(time_ns));
  } else {
    impl_->write(topic, m, ros_time(time_ns));
  }
}

void BagWriter::imu(const std::string& topic, std::int64_t time_ns, const std::string& frame_id,
                    const std::array<double, 3>& w, const std::array<double, 3>& a,
                    double gyro_variance, double accel_variance) {
  sensor_msgs::Imu m;
  m.header = impl_->numbered_header(topic, time_ns, frame_id);
  m.orientation.w = 1.0;
  m.orientation_covariance[0] = -1.0;
  m.angular_velocity.x = w[0];
  m.angular_velocity.y = w[1];
  m.angular_velocity.z = w[2];
  m.linear_acceleration.x = a[0];
  m.linear_acceleration.y = a[1];
  m.linear_acceleration.z = a[2];
  for (int i = 0; i < 3; ++i) {
    m.angular_velocity_covariance[4 * i] = gyro_variance;
    m.linear_acceleration_covariance[4 * i] = accel_variance;
  }
  impl_->write(topic, m, m.header.stamp);
}

void BagWriter::odometry(const std::string& topic, std::int64_t time_ns,
                         const std::string& frame_id, const std::string& child_frame,
                         const RigidTransform& pose, const Twist& twist) {
  nav_msgs::Odometry m;
  m.header = impl_->numbered_header(topic, time_ns, frame_id);
  m.child_frame_id = child_frame;
  m.pose.pose = pose_msg(pose);
  m.twist.twist.linear.x = twist.linear_mps[0];
  m.twist.twist.linear.y = twist.linear_mps[1];
  m.twist.twist.linear.z = twist.linear_mps[2];
  m.twist.twist.angular.x = twist.angular_radps[0];
  m.twist.twist.angular.y = twist.angular_radps[1];
  m.twist.twist.angular.z = twist.angular_radps[2];
  impl_->write(topic, m, m.header.stamp);
}

void BagWriter::pose(const std::string& topic, std::int64_t time_ns, const std::string& frame_id,
                     const RigidTransform& pose) {
  geometry_msgs::PoseStamped m;
  m.header = impl_->numbered_header(topic, time_ns, frame_id);
  m.pose = pose_msg(pose);
  impl_->write(topic, m, m.header.stamp);
}

void BagWriter::wifi_scan(const std::string& topic, std::int64_t time_ns,
                          const std::string& frame_id, std::int64_t scan_start_ns,
                          std::int64_t scan_end_ns, const std::vector<WifiEntry>& entries) {
  wifislam_msgs::WifiScan m;
  m.header = impl_->numbered_header(topic, time_ns, frame_id);
  m.scan_start = ros_time(scan_start_ns);
  m.scan_end = ros_time(scan_end_ns);
  for (const WifiEntry& e : entries) {
    m.bssid.push_back(e.bssid);
    m.frequency_mhz.push_back(e.frequency_mhz);
    m.rssi_dbm.push_back(e.rssi_dbm);
    m.ssid.push_back(e.ssid);
  }
  impl_->write(topic, m, m.header.stamp);
}

}  // namespace wifislam::interop::bag
