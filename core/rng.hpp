#pragma once
// Seeded random numbers with named sub-streams.
//
// Every consumer derives its own generator from the scene seed and a stream name, e.g.
// `Rng::stream(seed, "shadowing/ap17")`, so adding a random consumer never changes another
// consumer's numbers. The generator (xoshiro256**) and the distributions are written here rather
// than taken from <random> because the standard leaves distribution algorithms to the library
// vendor: std::normal_distribution gives different numbers under libstdc++ and libc++, and our
// datasets must be byte-identical wherever they are generated.

#include <bit>
#include <cstdint>
#include <string_view>

namespace wifislam {

/// 64-bit FNV-1a hash of a string: stable across platforms, used to name sub-streams.
std::uint64_t fnv1a64(std::string_view text);

class Rng {
 public:
  /// Generator for the sub-stream `name` of the run seeded with `seed`.
  static Rng stream(std::uint64_t seed, std::string_view name);
  explicit Rng(std::uint64_t state_seed);

  /// Inline: per-pixel consumers (the depth sensor model) draw ~60k of these a frame.
  std::uint64_t next_u64() {
    const std::uint64_t result = std::rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = std::rotl(s_[3], 45);
    return result;
  }
  /// Uniform in [0, 1) with 53 random bits.
  double uniform();
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform integer in [lo, hi] (inclusive), unbiased.
  std::int64_t uniform_int(std::int64_t lo, std::int64_t hi);
  /// Standard normal by the Marsaglia polar method (deterministic, no caching across calls
  /// other than the spare value held in this object).
  double normal();
  double normal(double mean, double stddev) { return mean + stddev * normal(); }
  bool bernoulli(double p) { return uniform() < p; }

  /// A child generator for a named sub-stream of this generator's stream.
  Rng child(std::string_view name) const;

 private:
  std::uint64_t s_[4];
  std::uint64_t origin_seed_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace wifislam
