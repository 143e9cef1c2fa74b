#pragma once
// Brute-force Hamming matching of ORB descriptors with Lowe's ratio test (the matches of OpenCV's
// BFMatcher knnMatch, k = 2).

#include <vector>

#include "slam/feature/frame_features.hpp"

namespace wifislam::slam::match {

struct MatchOptions {
  /// Lowe's ratio: keep a match when best distance < ratio * second best. Lower is stricter:
  /// fewer wrong matches on repetitive walls, fewer matches overall. RTAB-Map `Kp/NndrRatio` 0.8.
  double ratio = 0.8;
  /// Matches whose Hamming distance exceeds this are dropped (ORB descriptors have 256 bits).
  int max_hamming_distance = 80;
};

/// A correspondence: keypoint `query` of the first frame, keypoint `train` of the second.
struct FeatureMatch {
  int query = -1;
  int train = -1;
  int distance = 0;
};

/// Matches every keypoint of `query` against the keypoints of `train` that have depth (the 3-D
/// side of a 3-D/2-D correspondence); each train keypoint is used at most once. Deterministic
/// (brute force, no randomised index).
std::vector<FeatureMatch> match_descriptors(const feature::FrameFeatures& query,
                                            const feature::FrameFeatures& train,
                                            const MatchOptions& options);

}  // namespace wifislam::slam::match
