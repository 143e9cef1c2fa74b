// Cosine similarity of RSSI vectors weighted max(0, rssi - floor): its properties, and the
// vectorised index agreeing with the reference form.

#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.hpp"
#include "slam/wifi/signature_similarity.hpp"

namespace wifislam::slam {
namespace {

constexpr double kFloorDbm = -100.0;

wifi::WifiSignature sig(std::vector<wifi::ApStrength> s) {
  return wifi::WifiSignature(std::move(s));
}

TEST(WifiSimilarity, IdenticalSignaturesScoreOne) {
  const wifi::WifiSignature a = sig({{1, -40}, {2, -70}, {3, -85}});
  EXPECT_NEAR(wifi::cosine_similarity(a, a, kFloorDbm), 1.0, 1e-12);
}

TEST(WifiSimilarity, InvariantToScalingTheWeights) {
  // Weights (60, 30, 15) and (40, 20, 10): one is 2/3 of the other.
  const wifi::WifiSignature a = sig({{1, -40}, {2, -70}, {3, -85}});
  const wifi::WifiSignature b = sig({{1, -60}, {2, -80}, {3, -90}});
  EXPECT_NEAR(wifi::cosine_similarity(a, b, kFloorDbm), 1.0, 1e-12);
}

TEST(WifiSimilarity, MissingAccessPointsCountZero) {
  // a = (60, 30, 0), b = (60, 0, 30): cos = 3600 / (sqrt(4500) * sqrt(4500)) = 0.8.
  const wifi::WifiSignature a = sig({{1, -40}, {2, -70}});
  const wifi::WifiSignature b = sig({{1, -40}, {3, -70}});
  EXPECT_NEAR(wifi::cosine_similarity(a, b, kFloorDbm), 0.8, 1e-12);
  // No AP in common: orthogonal.
  EXPECT_NEAR(wifi::cosine_similarity(sig({{1, -40}}), sig({{2, -40}}), kFloorDbm), 0.0, 1e-12);
}

TEST(WifiSimilarity, ReadingsAtOrBelowTheFloorWeighNothing) {
  const wifi::WifiSignature a = sig({{1, -40}, {2, -105}});
  const wifi::WifiSignature b = sig({{1, -50}});
  EXPECT_NEAR(wifi::cosine_similarity(a, b, kFloorDbm), 1.0, 1e-12);
}

TEST(WifiSimilarity, EmptySignaturesAreSimilarToNothing) {
  const wifi::WifiSignature empty;
  const wifi::WifiSignature a = sig({{1, -40}});
  EXPECT_EQ(wifi::cosine_similarity(empty, a, kFloorDbm), 0.0);
  EXPECT_EQ(wifi::cosine_similarity(empty, empty, kFloorDbm), 0.0);
  EXPECT_EQ(wifi::cosine_similarity(sig({{1, -120}}), a, kFloorDbm), 0.0);
}

TEST(WifiSimilarity, IndexAgreesWithTheReferenceForManyRandomSignatures) {
  Rng rng = Rng::stream(3, "test/wifi/similarity");
  auto random_signature = [&] {
    std::vector<wifi::ApStrength> s;
    for (wifi::AccessPointKey ap = 0; ap < 150; ++ap) {
      if (rng.uniform() < 0.3) s.push_back({ap * 16, rng.uniform(-98.0, -30.0)});
    }
    return wifi::WifiSignature(std::move(s));
  };
  std::vector<wifi::WifiSignature> stored;
  wifi::SignatureSimilarityIndex index(kFloorDbm);
  for (int i = 0; i < 70; ++i) {  // grows past the initial row and column capacity
    stored.push_back(random_signature());
    EXPECT_EQ(index.add(stored.back()), i);
  }
  stored.push_back(wifi::WifiSignature());
  index.add(stored.back());
  for (int q = 0; q < 5; ++q) {
    const wifi::WifiSignature query = random_signature();
    const Eigen::VectorXd s = index.similarities(query);
    ASSERT_EQ(s.size(), static_cast<Eigen::Index>(stored.size()));
    for (std::size_t i = 0; i < stored.size(); ++i) {
      EXPECT_NEAR(s(static_cast<Eigen::Index>(i)),
                  wifi::cosine_similarity(query, stored[i], kFloorDbm), 1e-12);
    }
  }
}

}  // namespace
}  // namespace wifislam::slam
