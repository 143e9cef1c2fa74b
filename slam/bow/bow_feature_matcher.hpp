#pragma once
// ORB-SLAM2's ORBmatcher::SearchByBoW between two keyframes (Mur-Artal & Tardós 2017), the first
// gate a loop candidate must pass before the expensive geometric check (LoopClosing::ComputeSim3
// drops a candidate with fewer than 20 such matches). Features are compared only when the direct
// index puts them under the same vocabulary node; a match needs a Hamming distance of at most
// `max_distance` (TH_LOW, 50) and below `ratio` (0.75) x the second-best distance; each feature
// of `b` is matched at most once. The rotation-consistency check follows: the keypoint angle
// differences are binned into 30 bins and only matches in the three fullest bins are kept
// (ORBmatcher::ComputeThreeMaxima; a bin under 10 % of the fullest is not kept).

#include <vector>

#include <opencv2/core.hpp>

#include "slam/bow/bow_vector.hpp"
#include "slam/match/hamming_distances.hpp"

namespace wifislam::slam::bow {

/// What SearchByBoW needs of one keyframe.
struct BowKeyframe {
  std::vector<match::PackedDescriptor> descriptors;
  std::vector<float> angles_deg;  // cv::KeyPoint::angle, -1 when not computed
  FeatureVector direct_index;
};

struct BowMatchOptions {
  int max_distance = 50;  // ORBmatcher::TH_LOW
  double ratio = 0.75;    // LoopClosing::ComputeSim3's ORBmatcher(0.75, true)
  bool check_orientation = true;
};

/// Number of SearchByBoW matches of `a`'s features in `b`.
int count_bow_matches(const BowKeyframe& a, const BowKeyframe& b, const BowMatchOptions& options);

/// Packs an ORB descriptor matrix (CV_8U, 32 bytes a row).
std::vector<match::PackedDescriptor> pack_descriptors(const cv::Mat& descriptors);

}  // namespace wifislam::slam::bow
