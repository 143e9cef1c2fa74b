// The exhaustive 2-nearest search of RTAB-Map's vocabulary (slam/match/hamming_distances.hpp):
// whichever instructions the CPU gives it (AVX-512 eight at a time, popcnt, portable), the result
// is a plain scan's, ties to the lower index included; on random descriptors and on sets built
// to be full of ties and of counts that are not multiples of eight.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "slam/match/hamming_distances.hpp"

namespace wifislam::slam {
namespace {

match::NearestTwo scan(const match::PackedDescriptor& q,
                       const std::vector<match::PackedDescriptor>& words) {
  match::NearestTwo r;
  for (std::size_t w = 0; w < words.size(); ++w) {
    const int d = match::hamming_distance(q, words[w]);
    if (d < r.best) {
      r.second = r.best;
      r.best = d;
      r.best_index = w;
    } else if (d < r.second) {
      r.second = d;
    }
  }
  return r;
}

match::NearestTwo lanes_search(const match::PackedDescriptor& q,
                               const std::vector<match::PackedDescriptor>& words) {
  std::vector<std::uint64_t> lanes[4];
  for (const match::PackedDescriptor& d : words)
    for (int k = 0; k < 4; ++k) lanes[k].push_back(d[k]);
  const std::uint64_t* const pointers[4] = {lanes[0].data(), lanes[1].data(), lanes[2].data(),
                                            lanes[3].data()};
  return match::nearest_two(q.data(), pointers, words.size());
}

TEST(NearestTwo, EqualsAPlainScanTiesToTheLowerIndex) {
  std::mt19937_64 rng(7);
  for (std::size_t count : {0u, 1u, 2u, 7u, 8u, 9u, 15u, 16u, 17u, 1000u, 4099u}) {
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<match::PackedDescriptor> words(count);
      // Half the trials draw from a few bit patterns, so equal distances abound.
      const bool ties = trial % 2 == 1;
      for (auto& d : words) {
        for (auto& x : d) x = ties ? (rng() % 4) * 0x0f0f0f0f0f0f0f0fULL : rng();
      }
      match::PackedDescriptor q{};
      for (auto& x : q) x = ties ? (rng() % 4) * 0x0f0f0f0f0f0f0f0fULL : rng();
      const match::NearestTwo expected = scan(q, words), got = lanes_search(q, words);
      EXPECT_EQ(got.best, expected.best) << count;
      EXPECT_EQ(got.second, expected.second) << count;
      EXPECT_EQ(got.best_index, expected.best_index) << count;
    }
  }
}

}  // namespace
}  // namespace wifislam::slam
