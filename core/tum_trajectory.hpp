#pragma once
// TUM RGB-D trajectory files: one pose per line, "timestamp tx ty tz qx qy qz qw", '#' comments.
// Timestamps are written with 6 decimals (microseconds, as the TUM tools do), or 9 for a time with
// sub-microsecond digits (Timestamp::to_tum_string); translations and
// quaternion components are written in their shortest exact decimal form, so a trajectory
// written and read back is bit-for-bit the same. Reading rejects malformed lines with file:line.

#include <optional>
#include <string>
#include <string_view>
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

/// The largest coordinate a trajectory may hold: 1000 km from its origin is no indoor route, and
/// beyond it alignment and plots lose their meaning (1e308 overflows the plot's pixel mapping).
inline constexpr double kMaxTrajectoryCoordinateM = 1e6;

/// Reads a TUM trajectory. Throws ParseError("file:line", ...) for a line that does not have
/// eight numbers, has a non-finite value, a coordinate beyond kMaxTrajectoryCoordinateM, a zero
/// quaternion, or a timestamp not later than the previous one; IoError when the file cannot be
/// read.
Trajectory read_tum_trajectory(const std::string& path);

/// One trajectory line split into its fields, checked as read_tum_trajectory checks it (the
/// order of stamps aside). `where` is "file:line" for the ParseError.
StampedPose parse_tum_pose_fields(const std::vector<std::string_view>& fields,
                                  const std::string& where);

/// The rule every TUM list and trajectory reader applies to its stamps: each one later than the
/// previous (`last`, updated). Two samples at one instant are a duplicated line or a clock that
/// stood still, and pairing by time cannot tell them apart. ParseError naming `where` otherwise.
void require_later_stamp(std::optional<Timestamp>& last, Timestamp time, std::string_view field,
                         const std::string& where);

/// Writes atomically (temporary file + rename). `header` lines are written as '# ' comments.
void write_tum_trajectory(const std::string& path, const Trajectory& trajectory,
                          const std::vector<std::string>& header = {});

/// One line in TUM format, without the newline.
std::string format_tum_line(const StampedPose& pose);

}  // namespace wifislam
