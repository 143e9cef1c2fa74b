#include "slam/feature/orb_feature_extractor.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace wifislam::slam::feature {

std::size_t FrameFeatures::depth_count() const {
  return static_cast<std::size_t>(std::count(has_depth.begin(), has_depth.end(), 1));
}

std::optional<double> depth_at(const cv::Mat& depth_m, double u_px, double v_px) {
  // Pixel (u, v) holds the depth at its centre (OpenCV convention), so interpolate between the
  // four centres around the sub-pixel keypoint: on a wall seen at a slant the depth changes
  // quickly across pixels, and the nearest pixel's value would misplace the point. Across a depth
  // edge (or a missing reading) interpolation would invent a surface: take the nearest instead.
  const int u0 = static_cast<int>(std::floor(u_px));
  const int v0 = static_cast<int>(std::floor(v_px));
  const auto valid = [](float z) { return std::isfinite(z) && z > 0.0f; };
  if (u0 >= 0 && v0 >= 0 && u0 + 1 < depth_m.cols && v0 + 1 < depth_m.rows) {
    const float z00 = depth_m.at<float>(v0, u0), z01 = depth_m.at<float>(v0, u0 + 1);
    const float z10 = depth_m.at<float>(v0 + 1, u0), z11 = depth_m.at<float>(v0 + 1, u0 + 1);
    if (valid(z00) && valid(z01) && valid(z10) && valid(z11)) {
      const float lo = std::min({z00, z01, z10, z11}), hi = std::max({z00, z01, z10, z11});
      if (hi - lo <= 0.05f * lo) {
        const double a = u_px - u0, b = v_px - v0;
        return (1 - b) * ((1 - a) * z00 + a * z01) + b * ((1 - a) * z10 + a * z11);
      }
    }
  }
  const int u = static_cast<int>(std::lround(u_px));
  const int v = static_cast<int>(std::lround(v_px));
  if (u < 0 || v < 0 || u >= depth_m.cols || v >= depth_m.rows) return std::nullopt;
  const float z = depth_m.at<float>(v, u);
  if (!valid(z)) return std::nullopt;
  return z;
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
  // OpenCV's ORB maps a level-l keypoint to the full image as x * s_l, but the pyramid is made by
  // cv::resize, whose pixel centres sit at (x + 0.5) s_l - 0.5: without this shift, keypoints of
  // coarse levels are biased up-left by up to a pixel and a half, which skews the pose estimate.
  for (cv::KeyPoint& kp : out.keypoints) {
    const double s = std::pow(options_.scale_factor, kp.octave);
    kp.pt.x += static_cast<float>(0.5 * (s - 1.0));
    kp.pt.y += static_cast<float>(0.5 * (s - 1.0));
  }
  out.points_m.assign(out.keypoints.size(), Eigen::Vector3d::Zero());
  out.has_depth.assign(out.keypoints.size(), 0);
  if (frame.depth_m.empty()) return out;
  for (std::size_t i = 0; i < out.keypoints.size(); ++i) {
    const cv::Point2f& p = out.keypoints[i].pt;
    const std::optional<double> z = depth_at(frame.depth_m, p.x, p.y);
    if (!z || *z < options_.min_depth_m || *z > options_.max_depth_m) continue;
    out.points_m[i] = intrinsics_.back_project(p.x, p.y, *z);
    out.has_depth[i] = 1;
  }
  return out;
}

}  // namespace wifislam::slam::feature
