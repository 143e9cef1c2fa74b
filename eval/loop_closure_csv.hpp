#pragma once
// loop_closures.csv of a run folder (written by `wifislam slam`):
//   from_keyframe,to_keyframe,from_frame,to_frame,from_time,to_time,role,inliers,
//   rms_reprojection_px,tx,ty,tz,qx,qy,qz,qw
// t/q = estimated pose of `to` in the camera frame of `from`.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/pose.hpp"
#include "core/timestamp.hpp"

namespace wifislam::eval {

struct DetectedLoopClosure {
  std::int64_t from_keyframe = -1, to_keyframe = -1;
  std::int64_t from_frame = -1, to_frame = -1;
  Timestamp from_time, to_time;
  std::string role;
  std::int64_t inliers = 0;
  double rms_reprojection_px = 0.0;
  Pose from_to = Pose::Identity();  // estimated
  int line = 0;
};

/// Throws IoError (unreadable) or ParseError("file:line", column, ...) for a wrong header, a
/// wrong field count, a non-numeric or non-finite value, or a zero quaternion.
std::vector<DetectedLoopClosure> read_loop_closures_csv(const std::filesystem::path& path);

}  // namespace wifislam::eval
