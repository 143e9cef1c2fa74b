// match_descriptors finds BFMatcher's matches: the ratio test and the distance cap applied to
// cv::BFMatcher(NORM_HAMMING).knnMatch(k = 2) over the train keypoints with depth, each train
// keypoint kept for its closest query. Checked against OpenCV itself on random descriptors, on
// sets full of equal distances (where tie-breaking decides), and on counts that are not multiples
// of eight; the ORB-only input rule is checked too.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include <opencv2/features2d.hpp>

#include "core/error.hpp"
#include "slam/match/descriptor_matcher.hpp"

namespace wifislam::slam {
namespace {

/// `count` keypoints with 32-byte descriptors; `ties` draws each byte from four values, so equal
/// distances abound; about a quarter of the keypoints have no depth.
feature::FrameFeatures random_features(std::size_t count, bool ties, std::mt19937_64& rng) {
  feature::FrameFeatures f;
  f.descriptors.create(static_cast<int>(count), 32, CV_8U);
  for (int r = 0; r < f.descriptors.rows; ++r) {
    for (int c = 0; c < 32; ++c) {
      f.descriptors.at<std::uint8_t>(r, c) =
          static_cast<std::uint8_t>(ties ? (rng() % 4) * 0x55 : rng() % 256);
    }
  }
  f.keypoints.resize(count);
  f.points_m.resize(count);
  f.has_depth.resize(count);
  for (auto& d : f.has_depth) d = rng() % 4 != 0;
  return f;
}

/// What match_descriptors did with OpenCV's matcher, step for step.
std::vector<match::FeatureMatch> opencv_matches(const feature::FrameFeatures& query,
                                                const feature::FrameFeatures& train,
                                                const match::MatchOptions& options) {
  std::vector<int> train_rows;
  for (std::size_t i = 0; i < train.size(); ++i)
    if (train.has_depth[i]) train_rows.push_back(static_cast<int>(i));
  if (query.descriptors.empty() || train_rows.size() < 2) return {};
  cv::Mat train_descriptors(static_cast<int>(train_rows.size()), 32, CV_8U);
  for (std::size_t r = 0; r < train_rows.size(); ++r)
    train.descriptors.row(train_rows[r]).copyTo(train_descriptors.row(static_cast<int>(r)));
  std::vector<std::vector<cv::DMatch>> knn;
  cv::BFMatcher(cv::NORM_HAMMING, false).knnMatch(query.descriptors, train_descriptors, knn, 2);
  std::vector<match::FeatureMatch> all;
  for (const auto& pair : knn) {
    if (pair.size() < 2) continue;
    if (pair[0].distance > options.max_hamming_distance) continue;
    if (pair[0].distance >= options.ratio * pair[1].distance) continue;
    all.push_back({pair[0].queryIdx, train_rows[static_cast<std::size_t>(pair[0].trainIdx)],
                   static_cast<int>(pair[0].distance)});
  }
  std::vector<int> best_for_train(train.size(), -1);
  for (std::size_t m = 0; m < all.size(); ++m) {
    int& best = best_for_train[static_cast<std::size_t>(all[m].train)];
    if (best < 0 || all[m].distance < all[static_cast<std::size_t>(best)].distance)
      best = static_cast<int>(m);
  }
  std::vector<match::FeatureMatch> unique;
  for (std::size_t m = 0; m < all.size(); ++m)
    if (best_for_train[static_cast<std::size_t>(all[m].train)] == static_cast<int>(m))
      unique.push_back(all[m]);
  return unique;
}

TEST(MatchDescriptors, FindsOpenCvBruteForceMatchersMatchesTiesIncluded) {
  std::mt19937_64 rng(11);
  std::size_t compared = 0;
  for (const std::size_t train_count : {0u, 1u, 2u, 3u, 9u, 17u, 64u, 501u}) {
    for (int trial = 0; trial < 8; ++trial) {
      const bool ties = trial % 2 == 1;
      const feature::FrameFeatures query = random_features(300, ties, rng);
      const feature::FrameFeatures train = random_features(train_count, ties, rng);
      // Random descriptors sit ~128 bits apart: a loose cap and ratio let matches through.
      match::MatchOptions options;
      options.ratio = trial < 4 ? 0.8 : 0.99;
      options.max_hamming_distance = ties ? 256 : 120;
      const auto expected = opencv_matches(query, train, options);
      const auto got = match::match_descriptors(query, train, options);
      ASSERT_EQ(got.size(), expected.size()) << train_count << " trial " << trial;
      for (std::size_t m = 0; m < got.size(); ++m) {
        EXPECT_EQ(got[m].query, expected[m].query);
        EXPECT_EQ(got[m].train, expected[m].train);
        EXPECT_EQ(got[m].distance, expected[m].distance);
      }
      compared += got.size();
    }
  }
  // Not a vacuous comparison: many matches passed both tests.
  EXPECT_GT(compared, 500u);
}

TEST(MatchDescriptors, RefusesDescriptorsThatAreNotOrbsOrNotOnePerKeypoint) {
  std::mt19937_64 rng(3);
  const feature::FrameFeatures orb = random_features(10, false, rng);
  feature::FrameFeatures other = orb;
  other.descriptors = cv::Mat::zeros(10, 64, CV_8U);  // SURF-sized
  EXPECT_THROW(match::match_descriptors(orb, other, {}), Error);
  EXPECT_THROW(match::match_descriptors(other, orb, {}), Error);
  other.descriptors = cv::Mat::zeros(10, 32, CV_32F);
  EXPECT_THROW(match::match_descriptors(orb, other, {}), Error);
  // A descriptor row per keypoint: fewer rows would be read past the matrix's end.
  other.descriptors = orb.descriptors.rowRange(0, 9).clone();
  EXPECT_THROW(match::match_descriptors(orb, other, {}), Error);
  EXPECT_THROW(match::match_descriptors(other, orb, {}), Error);
}

}  // namespace
}  // namespace wifislam::slam
