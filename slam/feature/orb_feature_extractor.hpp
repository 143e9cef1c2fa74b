#pragma once
// ORB features (OpenCV) with a depth lookup per keypoint.

#include <optional>

#include <opencv2/features2d.hpp>

#include "core/camera_intrinsics.hpp"
#include "core/sensor_stream.hpp"
#include "slam/feature/frame_features.hpp"

namespace wifislam::slam::feature {

struct FeatureOptions {
  /// Keypoints per frame. More features: more matches and robustness, linear cost in
  /// extraction and quadratic in brute-force matching. RGBDSLAMv2 `max_keypoints` 600.
  int max_keypoints = 600;
  /// ORB pyramid: scale step and level count (OpenCV defaults 1.2 / 8).
  double scale_factor = 1.2;
  int pyramid_levels = 8;
  /// FAST threshold (OpenCV default 20). Lower finds corners on low-contrast walls.
  int fast_threshold = 20;
  /// Depth readings outside [min_depth_m, max_depth_m] are treated as missing. The Kinect v1's
  /// usable range is about 0.5-4.5 m; farther readings are noisy (sigma ~ z^2).
  double min_depth_m = 0.3;
  double max_depth_m = 6.0;

  friend bool operator==(const FeatureOptions&, const FeatureOptions&) = default;
};

/// Depth (m) at a sub-pixel position: bilinear between the four nearest pixel centres when they
/// agree within 5 %, else the nearest pixel's reading; nullopt when there is none.
std::optional<double> depth_at(const cv::Mat& depth_m, double u_px, double v_px);

class OrbFeatureExtractor {
 public:
  OrbFeatureExtractor(const FeatureOptions& options, const CameraIntrinsics& intrinsics);

  /// Detects and describes ORB keypoints on the grey image of `frame` and looks up their depth.
  FrameFeatures extract(const RgbdFrame& frame) const;

  const FeatureOptions& options() const { return options_; }

 private:
  FeatureOptions options_;
  CameraIntrinsics intrinsics_;
  cv::Ptr<cv::ORB> orb_;
};

}  // namespace wifislam::slam::feature
