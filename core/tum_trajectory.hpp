#pragma once
// TUM RGB-D trajectory files: one pose per line, "timestamp tx ty tz qx qy qz qw", '#' comments.
// Timestamps are written with 6 decimals (microseconds, as the TUM tools do), or 9 for a time with
// sub-microsecond digits (Timestamp::to_tum_string); translations and
// quaternion components are written in their shortest exact decimal form, so a trajectory
// written and read back is bit-for-bit the same. Reading rejects malformed lines with file:line.

#include <string>
#include <vector>

#include "core/pose.hpp"
#include "core/timestamp.hpp"

namespace wifislam {

struct StampedPose {
  Timestamp time;
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  // as read, not renormalised

  Pose pose() const { return pose_from_translation_quaternion(translation_m, rotation); }
  static StampedPose from_pose(Timestamp time, const Pose& pose);
};

using Trajectory = std::vector<StampedPose>;

/// Reads a TUM trajectory. Throws ParseError("file:line", ...) for a line that does not have
/// eight numbers, has a non-finite value, a zero quaternion, or a timestamp earlier than the
/// previous one; IoError when the file cannot be read.
Trajectory read_tum_trajectory(const std::string& path);

/// Writes atomically (temporary file + rename). `header` lines are written as '# ' comments.
void write_tum_trajectory(const std::string& path, const Trajectory& trajectory,
                          const std::vector<std::string>& header = {});

/// One line in TUM format, without the newline.
std::string format_tum_line(const StampedPose& pose);

}  // namespace wifislam
