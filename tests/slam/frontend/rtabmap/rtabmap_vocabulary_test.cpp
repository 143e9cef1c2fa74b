// RTAB-Map's incremental vocabulary: nearest-neighbour distance ratio quantisation, Kp/MaxFeatures,
// determinism, the rehearsal similarity, and the tf-idf likelihood's normalisation.

#include <gtest/gtest.h>

#include <cmath>

#include "slam/frontend/rtabmap/likelihood.hpp"
#include "slam/frontend/rtabmap/visual_vocabulary.hpp"
#include "tests/slam/frontend/rtabmap/rtabmap_test_nodes.hpp"

namespace wifislam::slam::frontend::rtabmap {
namespace {

cv::Mat descriptor_with_bits(std::initializer_list<int> bits) {
  cv::Mat row = cv::Mat::zeros(1, 32, CV_8U);
  for (int bit : bits)
    row.at<std::uint8_t>(0, bit / 8) |= static_cast<std::uint8_t>(1u << (bit % 8));
  return row;
}

TEST(RtabmapVocabulary, DescriptorJoinsNearestWordOnlyWhenTheRatioTestPasses) {
  VisualVocabulary vocabulary(0.8);
  cv::Mat first;
  first.push_back(descriptor_with_bits({}));  // word 0: all zeros
  first.push_back(
      descriptor_with_bits({0,  1,  2,  3,  4,  5,  6,  7,  8,  9,
                            10, 11, 12, 13, 14, 15, 16, 17, 18, 19}));  // word 1: 20 bits set
  const NodeWords a = vocabulary.add_node(0, first);
  ASSERT_EQ(vocabulary.size(), 2u);
  EXPECT_EQ(a.total, 2);

  cv::Mat second;
  second.push_back(descriptor_with_bits({100}));  // d = 1 to word 0, 21 to word 1: 1 <= 0.8 x 21
  second.push_back(descriptor_with_bits({0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));  // 10 and 10: ambiguous
  const NodeWords b = vocabulary.add_node(1, second);
  EXPECT_EQ(vocabulary.size(), 3u);  // the ambiguous one founded word 2
  EXPECT_EQ(b.counts.at(0), 1);
  EXPECT_EQ(b.counts.at(2), 1);
  EXPECT_EQ(vocabulary.references(0).size(), 2u);  // nodes 0 and 1
  EXPECT_EQ(vocabulary.references(2).size(), 1u);

  vocabulary.disable_references(1, b);
  EXPECT_EQ(vocabulary.references(0).size(), 1u);
  EXPECT_TRUE(vocabulary.references(2).empty());
  vocabulary.enable_references(1, b);
  EXPECT_EQ(vocabulary.references(0).at(1), 1);
}

TEST(RtabmapVocabulary, WordsOfNodesOutOfMemoryLeaveTheDictionaryUntilRetrieved) {
  // Memory::cleanUnusedWords: a word no node in memory references is not searched.
  VisualVocabulary vocabulary(0.8);
  const NodeWords place0 = vocabulary.add_node(0, test::place_features(0).descriptors);
  const std::size_t words = vocabulary.size();
  EXPECT_EQ(vocabulary.dictionary_size(), words);

  vocabulary.disable_references(0, place0);  // node 0 moves to LTM
  EXPECT_EQ(vocabulary.dictionary_size(), 0u);
  const std::int64_t before = vocabulary.distance_computations();
  const NodeWords copy = vocabulary.add_node(1, test::place_features(0).descriptors);
  // The same place again founds new words (and compares only with the ones it founds).
  EXPECT_GE(vocabulary.size(), words + 150);
  for (const auto& [word, count] : copy.counts) EXPECT_GE(word, static_cast<WordId>(words));
  EXPECT_LT(vocabulary.distance_computations() - before,
            static_cast<std::int64_t>(copy.total) * static_cast<std::int64_t>(words));

  vocabulary.enable_references(0, place0);  // retrieved: its words are searched again
  EXPECT_EQ(vocabulary.dictionary_size(), vocabulary.size());
  const NodeWords third = vocabulary.add_node(2, test::place_features(0).descriptors);
  bool reuses_an_old_word = false;
  for (const auto& [word, count] : third.counts) {
    reuses_an_old_word |= word < static_cast<WordId>(words);
  }
  EXPECT_TRUE(reuses_an_old_word);
}

TEST(RtabmapVocabulary, RevisitedPlaceReusesItsWordsAndNewPlaceFoundsNewOnes) {
  VisualVocabulary vocabulary(0.8);
  const feature::FrameFeatures place0 = test::place_features(0);
  const NodeWords first = vocabulary.add_node(0, place0.descriptors);
  const std::size_t after_first = vocabulary.size();
  EXPECT_GE(after_first, 150u);  // its own descriptors are new words
  const NodeWords again = vocabulary.add_node(1, test::place_features(0).descriptors);
  EXPECT_EQ(vocabulary.size(), after_first);  // noisy copies quantise to the same words
  EXPECT_GT(node_similarity(first, again), 0.6);
  const NodeWords other = vocabulary.add_node(2, test::place_features(7).descriptors);
  EXPECT_GE(vocabulary.size(), after_first + 150);
  EXPECT_LT(node_similarity(first, other), 0.2);
}

TEST(RtabmapVocabulary, SameDescriptorsGiveTheSameWords) {
  std::vector<feature::FrameFeatures> nodes;
  for (int p : {0, 1, 2, 0, 3, 1}) nodes.push_back(test::place_features(p));
  VisualVocabulary a(0.8), b(0.8);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const NodeWords wa = a.add_node(static_cast<NodeId>(i), nodes[i].descriptors);
    const NodeWords wb = b.add_node(static_cast<NodeId>(i), nodes[i].descriptors);
    EXPECT_EQ(wa.counts, wb.counts) << i;
  }
  EXPECT_EQ(a.size(), b.size());
}

TEST(RtabmapVocabulary, MaxFeaturesKeepsTheStrongestKeypoints) {
  const feature::FrameFeatures f = test::place_features(4);  // responses fall with the row
  const cv::Mat kept = strongest_descriptors(f.keypoints, f.descriptors, 120);
  ASSERT_EQ(kept.rows, 120);
  EXPECT_EQ(cv::norm(kept, f.descriptors.rowRange(0, 120), cv::NORM_HAMMING), 0.0);
  EXPECT_EQ(strongest_descriptors(f.keypoints, f.descriptors, 500).rows, f.descriptors.rows);
}

TEST(RtabmapLikelihood, NormalisationRaisesOnlyScoresAboveMeanPlusSigma) {
  // Non-zero scores 1, 1, 1, 5: mean 2, sigma sqrt(3).
  const NormalisedLikelihood l =
      normalise_likelihood({{0, 1.0}, {1, 1.0}, {2, 1.0}, {3, 5.0}, {4, 0.0}});
  EXPECT_DOUBLE_EQ(l.mean, 2.0);
  EXPECT_NEAR(l.stddev, std::sqrt(3.0), 1e-12);
  EXPECT_EQ(l.node.at(0), 1.0);
  EXPECT_EQ(l.node.at(4), 1.0);
  EXPECT_NEAR(l.node.at(3), (5.0 - (std::sqrt(3.0) - 1e-4)) / 2.0, 1e-12);
  EXPECT_NEAR(l.virtual_place, 2.0 / std::sqrt(3.0) + 1.0, 1e-12);
  // Flat scores: nothing stands out, the virtual place gets 2.
  EXPECT_EQ(normalise_likelihood({{0, 1.0}, {1, 1.0}}).virtual_place, 2.0);
}

}  // namespace
}  // namespace wifislam::slam::frontend::rtabmap
