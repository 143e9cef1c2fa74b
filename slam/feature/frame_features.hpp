#pragma once
// The features of one RGB-D frame: ORB keypoints and descriptors, and for each keypoint its 3-D
// point in the camera optical frame when the depth image has a valid reading there. Keypoints
// without depth stay: they can still be the 2-D side of a 3-D/2-D correspondence.

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/timestamp.hpp"

namespace wifislam::slam::feature {

struct FrameFeatures {
  Timestamp time;
  std::int64_t frame_index = 0;
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;  // CV_8U, one 32-byte ORB descriptor per row, same order as keypoints
  std::vector<Eigen::Vector3d> points_m;  // optical frame; valid only where has_depth[i]
  std::vector<std::uint8_t> has_depth;

  std::size_t size() const { return keypoints.size(); }
  std::size_t depth_count() const;
};

}  // namespace wifislam::slam::feature
