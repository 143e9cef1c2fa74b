#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/rng.hpp"

namespace wifislam {
namespace {

TEST(Rng, SameSeedAndStreamGiveTheSameNumbers) {
  Rng a = Rng::stream(42, "shadowing/ap17"), b = Rng::stream(42, "shadowing/ap17");
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(a.next_u64(), b.next_u64());
}

TEST(Rng, StreamsAreIndependentOfEachOtherAndOfTheSeed) {
  Rng a = Rng::stream(42, "shadowing/ap17"), b = Rng::stream(42, "shadowing/ap18"),
      c = Rng::stream(43, "shadowing/ap17");
  int same_ab = 0, same_ac = 0;
  for (int i = 0; i < 1000; ++i) {
    const auto x = a.next_u64();
    same_ab += x == b.next_u64();
    same_ac += x == c.next_u64();
  }
  EXPECT_EQ(same_ab, 0);
  EXPECT_EQ(same_ac, 0);
}

TEST(Rng, KnownValuesPinTheAlgorithm) {
  // Datasets must be byte-identical across machines and library versions: the generator and
  // the stream naming are part of the format. Changing either must be deliberate.
  Rng r = Rng::stream(1, "a");
  const std::uint64_t first = r.next_u64();
  Rng again(1 ^ fnv1a64("a"));
  EXPECT_EQ(first, again.next_u64());
  EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cULL);
}

TEST(Rng, UniformAndNormalHaveTheRightMoments) {
  Rng r = Rng::stream(7, "moments");
  const int n = 200000;
  double sum = 0, sum2 = 0, usum = 0;
  for (int i = 0; i < n; ++i) {
    const double x = r.normal(2.0, 3.0);
    sum += x;
    sum2 += x * x;
    const double u = r.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    usum += u;
  }
  const double mean = sum / n, var = sum2 / n - mean * mean;
  EXPECT_NEAR(mean, 2.0, 0.03);
  EXPECT_NEAR(std::sqrt(var), 3.0, 0.03);
  EXPECT_NEAR(usum / n, 0.5, 0.005);
}

TEST(Rng, UniformIntCoversTheInclusiveRangeEvenly) {
  Rng r = Rng::stream(3, "ints");
  std::vector<int> counts(6, 0);
  for (int i = 0; i < 60000; ++i) {
    const auto k = r.uniform_int(-2, 3);
    ASSERT_GE(k, -2);
    ASSERT_LE(k, 3);
    ++counts[k + 2];
  }
  for (int c : counts) EXPECT_NEAR(c, 10000, 400);
}

}  // namespace
}  // namespace wifislam
