#include "slam/match/descriptor_matcher.hpp"

#include <vector>

#include <opencv2/features2d.hpp>

namespace wifislam::slam::match {

std::vector<FeatureMatch> match_descriptors(const feature::FrameFeatures& query,
                                            const feature::FrameFeatures& train,
                                            const MatchOptions& options) {
  std::vector<FeatureMatch> out;
  if (query.descriptors.empty() || train.descriptors.empty()) return out;

  // Only train keypoints with depth take part, so the ratio test compares usable candidates.
  std::vector<int> train_rows;
  train_rows.reserve(train.size());
  for (std::size_t i = 0; i < train.size(); ++i) {
    if (train.has_depth[i]) train_rows.push_back(static_cast<int>(i));
  }
  if (train_rows.size() < 2) return out;
  cv::Mat train_descriptors(static_cast<int>(train_rows.size()), train.descriptors.cols,
                            train.descriptors.type());
  for (std::size_t r = 0; r < train_rows.size(); ++r) {
    train.descriptors.row(train_rows[r]).copyTo(train_descriptors.row(static_cast<int>(r)));
  }

  cv::BFMatcher matcher(cv::NORM_HAMMING, false);
  std::vector<std::vector<cv::DMatch>> knn;
  matcher.knnMatch(query.descriptors, train_descriptors, knn, 2);
  out.reserve(knn.size());
  for (const auto& pair : knn) {
    if (pair.size() < 2) continue;
    const cv::DMatch& best = pair[0];
    if (best.distance > options.max_hamming_distance) continue;
    if (best.distance >= options.ratio * pair[1].distance) continue;
    out.push_back({best.queryIdx, train_rows[static_cast<std::size_t>(best.trainIdx)],
                   static_cast<int>(best.distance)});
  }
  // One train keypoint answers at most one query (the closest): repeated texture otherwise
  // funnels many queries onto the same 3-D point and RANSAC sees them as agreeing.
  std::vector<int> best_for_train(train.size(), -1);
  for (std::size_t m = 0; m < out.size(); ++m) {
    int& best = best_for_train[static_cast<std::size_t>(out[m].train)];
    if (best < 0 || out[m].distance < out[static_cast<std::size_t>(best)].distance) {
      best = static_cast<int>(m);
    }
  }
  std::vector<FeatureMatch> unique;
  unique.reserve(out.size());
  for (std::size_t m = 0; m < out.size(); ++m) {
    if (best_for_train[static_cast<std::size_t>(out[m].train)] == static_cast<int>(m)) {
      unique.push_back(out[m]);
    }
  }
  return unique;
}

}  // namespace wifislam::slam::match
