// Cluster management exactly as the paper's "General approach": join the similar cluster the
// keyframe has a visual edge into (the most similar when several), otherwise found a new cluster
// represented by the keyframe's own signature.

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "slam/wifi/wifi_cluster_map.hpp"

namespace wifislam::slam {
namespace {

constexpr double kThreshold = 0.9;
constexpr double kRssiFloorDbm = -100.0;

std::shared_ptr<const wifi::WifiSignature> shared_signature(std::vector<wifi::ApStrength> s) {
  return std::make_shared<const wifi::WifiSignature>(std::move(s));
}

// Three places: A and A2 close (similar), B far from both.
const auto kSignatureA = shared_signature({{0x10, -40}, {0x20, -60}, {0x30, -90}});
const auto kSignatureA2 = shared_signature({{0x10, -42}, {0x20, -58}, {0x30, -88}});
const auto kSignatureB = shared_signature({{0x10, -90}, {0x20, -60}, {0x30, -40}});

TEST(WifiClusters, NoSimilarClusterFoundsANewOne) {
  wifi::WifiClusterMap map(kThreshold, kRssiFloorDbm);
  EXPECT_TRUE(map.similar_clusters(*kSignatureA).empty());
  EXPECT_EQ(map.assign(0, kSignatureA, {}, {}), 0);
  const auto similar = map.similar_clusters(*kSignatureB);
  EXPECT_TRUE(similar.empty());
  EXPECT_EQ(map.assign(1, kSignatureB, similar, {0}), 1);  // visual edge, but cluster 0 not similar
  ASSERT_EQ(map.clusters().size(), 2u);
  EXPECT_EQ(map.clusters()[1].founder, 1);
  EXPECT_EQ(*map.clusters()[1].representative, *kSignatureB);
}

TEST(WifiClusters, SimilarClusterWithAVisualEdgeIsJoined) {
  wifi::WifiClusterMap map(kThreshold, kRssiFloorDbm);
  map.assign(0, kSignatureA, {}, {});
  const auto similar = map.similar_clusters(*kSignatureA2);
  ASSERT_EQ(similar.size(), 1u);
  EXPECT_GT(similar[0].similarity, kThreshold);
  EXPECT_EQ(map.assign(1, kSignatureA2, similar, {0}), 0);
  EXPECT_EQ(map.clusters()[0].keyframes, (std::vector<graph::KeyframeId>{0, 1}));
  EXPECT_EQ(*map.clusters()[0].representative, *kSignatureA);  // the founder's stays
}

TEST(WifiClusters, SimilarButNoVisualEdgeFoundsANewCluster) {
  wifi::WifiClusterMap map(kThreshold, kRssiFloorDbm);
  map.assign(0, kSignatureA, {}, {});
  const auto similar = map.similar_clusters(*kSignatureA2);
  ASSERT_EQ(similar.size(), 1u);
  EXPECT_EQ(map.assign(1, kSignatureA2, similar, {}), 1);
  EXPECT_EQ(map.cluster_of(1), 1);
}

TEST(WifiClusters, SeveralSimilarClustersWithEdgesTheMostSimilarWins) {
  wifi::WifiClusterMap map(kThreshold, kRssiFloorDbm);
  // Two clusters founded at nearby places (no visual edge between them).
  map.assign(0, kSignatureA, {}, {});
  map.assign(1, kSignatureA2, map.similar_clusters(*kSignatureA2), {});
  ASSERT_EQ(map.clusters().size(), 2u);
  // A query exactly at A2: both clusters similar, A2's cluster (1) the most.
  const auto similar = map.similar_clusters(*kSignatureA2);
  ASSERT_EQ(similar.size(), 2u);
  EXPECT_EQ(similar[0].cluster, 1);
  EXPECT_EQ(similar[1].cluster, 0);
  EXPECT_EQ(map.assign(2, kSignatureA2, similar, {0, 1}), 1);
  // With an edge only into the less similar cluster, that one is joined.
  EXPECT_EQ(map.assign(3, kSignatureA2, similar, {0}), 0);
}

TEST(WifiClusters, AKeyframeWithoutSignatureJoinsNone) {
  wifi::WifiClusterMap map(kThreshold, kRssiFloorDbm);
  EXPECT_EQ(map.assign(0, nullptr, {}, {}), -1);
  EXPECT_EQ(map.cluster_of(0), -1);
  EXPECT_TRUE(map.clusters().empty());
  EXPECT_EQ(map.assign(1, kSignatureA, {}, {0}), 0);
}

TEST(WifiClusters, KeyframesMustArriveInOrder) {
  wifi::WifiClusterMap map(kThreshold, kRssiFloorDbm);
  map.assign(3, kSignatureA, {}, {});
  EXPECT_THROW(map.assign(2, kSignatureA, {}, {}), InvalidInputError);
}

TEST(WifiClusters, CsvListsRepresentativeAndKeyframes) {
  wifi::WifiClusterMap map(kThreshold, kRssiFloorDbm);
  map.assign(0, kSignatureA, {}, {});
  map.assign(1, kSignatureA2, map.similar_clusters(*kSignatureA2), {0});
  map.assign(2, kSignatureB, map.similar_clusters(*kSignatureB), {1});
  EXPECT_EQ(map.to_csv(),
            "cluster_id,founder_keyframe,keyframes,representative_signature\n"
            "0,0,0 1,00:00:00:00:00:10=-40.0;00:00:00:00:00:20=-60.0;00:00:00:00:00:30=-90.0\n"
            "1,2,2,00:00:00:00:00:10=-90.0;00:00:00:00:00:20=-60.0;00:00:00:00:00:30=-40.0\n");
}

}  // namespace
}  // namespace wifislam::slam
