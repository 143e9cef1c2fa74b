#include "slam/feature/orb_feature_extractor.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace wifislam::slam {

std::size_t FrameFeatures::depth_count() const {
  return static_cast<std::size_t>(std::count(has_depth.begin(), has_depth.end(), 1));
}

OrbFeatureExtractor::OrbFeatureExtractor(const FeatureOptions& options,
                                         const CameraIntrinsics& intrinsics)
    : options_(options), intrinsics_(intrinsics) {
  if (options.max_keypoints < 8)
    throw InvalidInputError("max_keypoints must be at least 8, got " +
                            std::to_string(options.max_keypoints));
  orb_ = cv::ORB::create(options.max_keypoints, static_cast<float>(options.scale_factor),
                         options.pyramid_levels, 31, 0, 2, cv::ORB::HARRIS_SCORE, 31,
                         options.fast_threshold);
}

FrameFeatures OrbFeatureExtractor::extract(const RgbdFrame& frame) const {
  FrameFeatures out;
  out.time = frame.time;
  out.frame_index = frame.index;
  if (frame.rgb.empty()) return out;
  cv::Mat grey;
  if (frame.rgb.channels() == 3) {
    cv::cvtColor(frame.rgb, grey, cv::COLOR_BGR2GRAY);
  } else {
    grey = frame.rgb;
  }
  orb_->detectAndCompute(grey, cv::noArray(), out.keypoints, out.descriptors);
  out.points_m.assign(out.keypoints.size(), Eigen::Vector3d::Zero());
  out.has_depth.assign(out.keypoints.size(), 0);
  if (frame.depth_m.empty()) return out;
  for (std::size_t i = 0; i < out.keypoints.size(); ++i) {
    const cv::Point2f& p = out.keypoints[i].pt;
    const int u = static_cast<int>(std::lround(p.x));
    const int v = static_cast<int>(std::lround(p.y));
    if (u < 0 || v < 0 || u >= frame.depth_m.cols || v >= frame.depth_m.rows) continue;
    const float z = frame.depth_m.at<float>(v, u);
    if (!std::isfinite(z) || z < options_.min_depth_m || z > options_.max_depth_m) continue;
    out.points_m[i] = intrinsics_.back_project(p.x, p.y, z);
    out.has_depth[i] = 1;
  }
  return out;
}

}  // namespace wifislam::slam
