#pragma once
// When the pipeline makes a keyframe, for a family that decides it by time and motion rather than
// by tracking quality. RTAB-Map makes a node at most every 1 / Rtabmap/DetectionRate seconds, and
// only when the robot has moved RGBD/LinearUpdate metres or turned RGBD/AngularUpdate radians
// since the last node; its odometry runs in between, on every frame.

#include <cstdint>

#include "core/pose.hpp"
#include "core/timestamp.hpp"

namespace wifislam::slam::frontend {

struct KeyframeSchedule {
  /// Least time between two keyframes (1 / detection rate).
  double period_s = 1.0;
  /// ... and the least motion since the last keyframe: either bound suffices.
  double min_translation_m = 0.1;
  double min_rotation_rad = 0.1;

  /// Whether a frame `elapsed` after the last keyframe, at `keyframe_from_frame` from it, is the
  /// next keyframe. Frame times are sampled, so a period of k frame intervals is met at the k-th
  /// frame (1 ms tolerance).
  bool due(std::int64_t elapsed_ns, const Pose& keyframe_from_frame) const;
};

}  // namespace wifislam::slam::frontend
