#include "sim/render/normal_deviates.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>

#include <boost/math/special_functions/erf.hpp>

namespace wifislam::sim::render {

const NormalQuantileTable& normal_quantiles() {
  static const NormalQuantileTable table = [] {
    std::array<double, 1 << kNormalQuantileBits> q{};
    double sum_sq = 0.0;
    for (std::size_t i = 0; i < q.size(); ++i) {
      const double p = (static_cast<double>(i) + 0.5) / static_cast<double>(q.size());
      q[i] = -std::numbers::sqrt2 * boost::math::erfc_inv(2.0 * p);
      sum_sq += q[i] * q[i];
    }
    const double scale = 1.0 / std::sqrt(sum_sq / static_cast<double>(q.size()));
    NormalQuantileTable t{};
    for (std::size_t i = 0; i < q.size(); ++i) t[i] = static_cast<float>(q[i] * scale);
    return t;
  }();
  return table;
}

void fill_normals(Rng& rng, float* out, int count) {
  const auto& table = normal_quantiles();
  constexpr std::uint64_t kMask = (1u << kNormalQuantileBits) - 1;
  constexpr int kPerDraw = 64 / kNormalQuantileBits;
  int i = 0;
  // Unrolled, each index shifted out of the draw directly: a loop over a running shift made
  // every lookup wait for the previous one, and fill_normals was ~40 % of the depth sensor
  // model's time.
  for (; i + kPerDraw <= count; i += kPerDraw) {
    const std::uint64_t bits = rng.next_u64();
#pragma GCC unroll 8
    for (int k = 0; k < kPerDraw; ++k)
      out[i + k] = table[(bits >> (k * kNormalQuantileBits)) & kMask];
  }
  for (std::uint64_t bits = rng.next_u64(); i < count; ++i, bits >>= kNormalQuantileBits) {
    out[i] = table[bits & kMask];
  }
}

}  // namespace wifislam::sim::render
