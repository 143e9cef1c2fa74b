// ORB-SLAM2's loop detection over BoW vectors (slam/bow): the keyframe database's inverted index
// and DetectLoopCandidates (shared-word cut at 0.8 of the most, minimum score, covisibility groups
// accumulating their scores, 0.75 of the best group), and the temporal consistency of candidates
// over three consecutive keyframes, on hand-built vectors whose answers are worked out here.
#include <gtest/gtest.h>

#include "slam/bow/bow_feature_matcher.hpp"
#include "slam/bow/keyframe_database.hpp"
#include "slam/bow/loop_consistency.hpp"

namespace wifislam::slam::bow {
namespace {

BowVector normalised(BowVector v) {
  l1_normalise(v);
  return v;
}

TEST(KeyframeDatabase, InvertedIndexListsTheKeyframesOfEachWordAndForgetsErasedOnes) {
  KeyframeDatabase db;
  db.add(5, {{1, 0.5}, {2, 0.5}});
  db.add(3, {{2, 1.0}});
  db.add(8, {{1, 1.0}});
  EXPECT_EQ(db.keyframes_with(1), (std::vector<graph::KeyframeId>{5, 8}));
  EXPECT_EQ(db.keyframes_with(2), (std::vector<graph::KeyframeId>{3, 5}));
  EXPECT_TRUE(db.keyframes_with(7).empty());
  db.erase(5);
  EXPECT_EQ(db.keyframes_with(1), (std::vector<graph::KeyframeId>{8}));
  EXPECT_EQ(db.keyframes_with(2), (std::vector<graph::KeyframeId>{3}));
  EXPECT_FALSE(db.contains(5));
  EXPECT_THROW(db.add(3, {{4, 1.0}}), std::logic_error);
}

TEST(KeyframeDatabase, LoopCandidatesFollowDetectLoopCandidates) {
  const BowVector query = normalised({{1, 1}, {2, 1}, {3, 1}, {4, 1}});
  KeyframeDatabase db;
  db.add(1, normalised({{1, 1}, {2, 1}, {3, 1}, {4, 1}}));          // 4 shared, score 1
  db.add(2, normalised({{1, 1}, {2, 1}, {3, 1}, {9, 1}}));          // 3 shared: not over 3.2
  db.add(3, normalised({{1, 1}, {2, 1}, {3, 1}, {4, 1}}));          // connected to the query
  db.add(4, normalised({{1, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 4}}));  // 4 shared, score 0.5
  db.add(5, normalised({{1, 3}, {2, 3}, {3, 1}, {4, 1}, {6, 2}}));  // 4 shared, score 0.7
  const auto neighbours = [](graph::KeyframeId k) {
    if (k == 1) return std::vector<graph::KeyframeId>{5, 2};
    if (k == 5) return std::vector<graph::KeyframeId>{1};
    return std::vector<graph::KeyframeId>{};
  };
  EXPECT_NEAR(l1_score(query, db.vector_of(4)), 0.5, 1e-12);
  EXPECT_NEAR(l1_score(query, db.vector_of(5)), 0.7, 1e-12);

  // Scored: 1 (1.0), 4 (0.5), 5 (0.7); 2 shares too few words (2 neighbours 1 but adds nothing).
  // Groups: 1 + 5 = 1.7 (best 1), 4 = 0.5, 5 + 1 = 1.7 (best 1). Over 0.75 x 1.7: keyframe 1 once.
  auto candidates = db.loop_candidates(query, {3}, 0.4, neighbours);
  ASSERT_EQ(candidates.size(), 1u);
  EXPECT_EQ(candidates[0].keyframe, 1);
  EXPECT_NEAR(candidates[0].score, 1.0, 1e-12);
  EXPECT_NEAR(candidates[0].accumulated_score, 1.7, 1e-12);
  EXPECT_EQ(db.last_postings_read(), 5u + 5u + 5u + 4u);  // words 1, 2, 3 in all five; 4 in four

  // Without the covisibility groups every scored keyframe over 0.75 of the best stands alone.
  candidates = db.loop_candidates(
      query, {3}, 0.4, [](graph::KeyframeId) { return std::vector<graph::KeyframeId>{}; });
  ASSERT_EQ(candidates.size(), 1u);  // 0.7 and 0.5 are not over 0.75
  candidates = db.loop_candidates(
      query, {3, 1}, 0.4, [](graph::KeyframeId) { return std::vector<graph::KeyframeId>{}; });
  ASSERT_EQ(candidates.size(), 1u);  // 5 (0.7); 4 (0.5) is not over 0.525
  EXPECT_EQ(candidates[0].keyframe, 5);
  // A minimum score above every score (ORB-SLAM2: the query's covisible keyframes score higher)
  // leaves nothing.
  EXPECT_TRUE(db.loop_candidates(query, {3}, 1.01, neighbours).empty());
  EXPECT_TRUE(db.loop_candidates(normalised({{42, 1}}), {}, 0.0, neighbours).empty());
}

// The Wi-Fi variant's query over the indexes of its similar clusters is DetectLoopCandidates over
// their union: the same candidates and scores as one index holding all of their keyframes, and
// keyframes of an index not searched are never returned.
TEST(KeyframeDatabase, AQueryOverSeveralIndexesIsAQueryOverTheirUnion) {
  const BowVector query = normalised({{1, 1}, {2, 1}, {3, 1}, {4, 1}});
  const std::vector<std::pair<graph::KeyframeId, BowVector>> keyframes = {
      {1, normalised({{1, 1}, {2, 1}, {3, 1}, {4, 1}})},
      {2, normalised({{1, 1}, {2, 1}, {3, 1}, {9, 1}})},
      {4, normalised({{1, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 4}})},
      {5, normalised({{1, 3}, {2, 3}, {3, 1}, {4, 1}, {6, 2}})},
      {7, normalised({{1, 2}, {2, 1}, {3, 1}, {4, 3}})}};
  KeyframeDatabase all, odd, even;
  for (const auto& [k, v] : keyframes) {
    all.add(k, v);
    (k % 2 ? odd : even).add(k, v);
  }
  const auto neighbours = [](graph::KeyframeId k) {
    if (k == 1) return std::vector<graph::KeyframeId>{5, 7};
    if (k == 5) return std::vector<graph::KeyframeId>{1, 4};
    return std::vector<graph::KeyframeId>{4};
  };
  const auto expected = all.loop_candidates(query, {}, 0.3, neighbours);
  std::size_t postings = 0;
  const auto split = loop_candidates({&odd, &even}, query, {}, 0.3, neighbours, &postings);
  ASSERT_FALSE(expected.empty());
  ASSERT_EQ(split.size(), expected.size());
  for (std::size_t i = 0; i < split.size(); ++i) {
    EXPECT_EQ(split[i].keyframe, expected[i].keyframe);
    EXPECT_DOUBLE_EQ(split[i].score, expected[i].score);
    EXPECT_DOUBLE_EQ(split[i].accumulated_score, expected[i].accumulated_score);
  }
  EXPECT_EQ(postings, all.last_postings_read());
  // Only the odd index: no even keyframe, and fewer postings read.
  const auto odd_only = loop_candidates({&odd}, query, {}, 0.3, neighbours, &postings);
  for (const LoopCandidate& c : odd_only) EXPECT_EQ(c.keyframe % 2, 1) << c.keyframe;
  EXPECT_LT(postings, all.last_postings_read());
}

// ORB-SLAM2's SearchByBoW: features meet only under the same direct-index node, a match needs
// distance <= 50 and under 0.75 x the second best, each feature of the other keyframe is taken
// once, and matches outside the three fullest rotation bins are dropped.
TEST(BowFeatureMatcher, CountsSearchByBowMatches) {
  const auto descriptor = [](std::uint64_t bits) { return match::PackedDescriptor{bits, 0, 0, 0}; };
  BowKeyframe a, b;
  // Node 1: a0 matches b0 at distance 1 (second best b1 at 30: 1 < 22.5).
  // Node 1: a1 is ambiguous (b2 at 2 bits, b3 at 2 bits: 2 < 1.5 fails).
  // Node 2: a2's best is 60 bits away: over TH_LOW.
  // Node 3: a3 would match b5, but b5 sits under node 4.
  a.descriptors = {descriptor(0b1), descriptor(0xF0), descriptor(0), descriptor(0x5)};
  a.angles_deg = {10, 10, 10, 10};
  a.direct_index = {{1, {0, 1}}, {2, {2}}, {3, {3}}};
  b.descriptors = {descriptor(0b11), descriptor((1ull << 30) - 1), descriptor(0xF3),
                   descriptor(0xFC), descriptor((1ull << 60) - 1), descriptor(0x5)};
  b.angles_deg = {12, 12, 12, 12, 12, 12};
  b.direct_index = {{1, {0, 1, 2, 3}}, {2, {4}}, {4, {5}}};
  EXPECT_EQ(count_bow_matches(a, b, {}), 1);
  BowMatchOptions loose;
  loose.ratio = 1.01;
  EXPECT_EQ(count_bow_matches(a, b, loose), 2);  // a1 now takes b2 (first of the ties)
  loose.max_distance = 64;
  EXPECT_EQ(count_bow_matches(a, b, loose), 3);  // and a2 takes b4

  // Rotation consistency: 20 matches turned by 0 degrees, 1 by 90 (a bin of its own, under a
  // tenth of the fullest: dropped).
  BowKeyframe c, d;
  for (int i = 0; i < 21; ++i) {
    c.descriptors.push_back(descriptor(1ull << i));
    d.descriptors.push_back(descriptor(1ull << i));
    c.angles_deg.push_back(i == 20 ? 100.0f : 10.0f);
    d.angles_deg.push_back(10.0f);
    c.direct_index[static_cast<NodeId>(i)] = {i};
    d.direct_index[static_cast<NodeId>(i)] = {i};
  }
  EXPECT_EQ(count_bow_matches(c, d, {}), 20);
  BowMatchOptions no_orientation;
  no_orientation.check_orientation = false;
  EXPECT_EQ(count_bow_matches(c, d, no_orientation), 21);
}

TEST(LoopConsistency, ACandidateIsAcceptedAfterThreeConsecutiveConsistentQueries) {
  LoopConsistency consistency;
  EXPECT_TRUE(consistency.update({{10, {9, 10, 11}}}).empty());   // new group: 0
  EXPECT_TRUE(consistency.update({{11, {10, 11, 12}}}).empty());  // 1
  // A look-alike elsewhere starts its own count at 0 beside the consistent one.
  EXPECT_TRUE(consistency.update({{12, {11, 12, 13}}, {50, {49, 50, 51}}}).empty());  // 2 and 0
  EXPECT_EQ(consistency.update({{13, {12, 13, 14}}, {51, {50, 51, 52}}}),
            (std::vector<graph::KeyframeId>{13}));  // 3: enough; the look-alike only 1
  // A query without candidates forgets every group: counting starts over.
  EXPECT_TRUE(consistency.update({}).empty());
  EXPECT_EQ(consistency.kept_groups(), 0u);
  EXPECT_TRUE(consistency.update({{14, {13, 14, 15}}}).empty());
}

}  // namespace
}  // namespace wifislam::slam::bow
