#include "slam/match/descriptor_matcher.hpp"

#include <cstdint>
#include <vector>

#include "core/error.hpp"
#include "slam/match/packed_descriptor.hpp"

namespace wifislam::slam::match {

namespace {

/// ORB's descriptors, one row per keypoint, as the feature extractor writes them
/// (frame_features.hpp): rows are read by keypoint index without bounds checks.
void check_orb_descriptors(const feature::FrameFeatures& features, const char* side) {
  if (!are_orb_descriptors(features.descriptors)) {
    throw Error(std::string("match_descriptors: the ") + side +
                " descriptors are not 32-byte ORB descriptors (CV_8U, 32 columns)");
  }
  if (static_cast<std::size_t>(features.descriptors.rows) != features.size() ||
      features.has_depth.size() != features.size()) {
    throw Error(std::string("match_descriptors: the ") + side +
                " frame's descriptors, keypoints and depth flags differ in number");
  }
}

}  // namespace

std::vector<FeatureMatch> match_descriptors(const feature::FrameFeatures& query,
                                            const feature::FrameFeatures& train,
                                            const MatchOptions& options) {
  std::vector<FeatureMatch> out;
  if (query.descriptors.empty() || train.descriptors.empty()) return out;
  check_orb_descriptors(query, "query");
  check_orb_descriptors(train, "train");

  // Only train keypoints with depth take part, so the ratio test compares usable candidates.
  std::vector<int> train_rows;
  train_rows.reserve(train.size());
  for (std::size_t i = 0; i < train.size(); ++i) {
    if (train.has_depth[i]) train_rows.push_back(static_cast<int>(i));
  }
  if (train_rows.size() < 2) return out;
  // The exhaustive 2-nearest search of cv::BFMatcher(NORM_HAMMING).knnMatch(k = 2), done by
  // hamming_distances' nearest_two. Both scan the train rows in order, keep the first row at the
  // smallest distance and count a tie with it as the second distance (OpenCV's batchDistance), so
  // the matches are BFMatcher's; tests/slam/match checks them against BFMatcher itself. Why not
  // BFMatcher: it computes each pair through a call to a generic-length normHamming, which made
  // this search 15% of a SLAM run's CPU time under perf; nearest_two compares eight pairs at once
  // where the CPU has AVX-512 VPOPCNTDQ.
  std::vector<std::uint64_t> lanes[4];
  for (auto& lane : lanes) lane.resize(train_rows.size());
  for (std::size_t r = 0; r < train_rows.size(); ++r) {
    const PackedDescriptor d = packed_descriptor(train.descriptors, train_rows[r]);
    for (std::size_t k = 0; k < 4; ++k) lanes[k][r] = d[k];
  }
  const std::uint64_t* const lane_data[4] = {lanes[0].data(), lanes[1].data(), lanes[2].data(),
                                             lanes[3].data()};
  out.reserve(query.size());
  for (int q = 0; q < query.descriptors.rows; ++q) {
    const PackedDescriptor d = packed_descriptor(query.descriptors, q);
    const NearestTwo nearest = nearest_two(d.data(), lane_data, train_rows.size());
    if (nearest.best > options.max_hamming_distance) continue;
    if (nearest.best >= options.ratio * nearest.second) continue;
    out.push_back({q, train_rows[nearest.best_index], nearest.best});
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
