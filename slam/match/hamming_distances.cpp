#include "slam/match/hamming_distances.hpp"

namespace wifislam::slam {

namespace {

void distances_portable(const std::uint64_t* query, const std::uint64_t* words, std::size_t count,
                        int* out) {
  for (std::size_t w = 0; w < count; ++w) {
    const std::uint64_t* word = words + 4 * w;
    out[w] = std::popcount(query[0] ^ word[0]) + std::popcount(query[1] ^ word[1]) +
             std::popcount(query[2] ^ word[2]) + std::popcount(query[3] ^ word[3]);
  }
}

#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target("popcnt"))) void distances_with_popcnt(const std::uint64_t* query,
                                                             const std::uint64_t* words,
                                                             std::size_t count, int* out) {
  for (std::size_t w = 0; w < count; ++w) {
    const std::uint64_t* word = words + 4 * w;
    out[w] = std::popcount(query[0] ^ word[0]) + std::popcount(query[1] ^ word[1]) +
             std::popcount(query[2] ^ word[2]) + std::popcount(query[3] ^ word[3]);
  }
}
#endif

}  // namespace

void hamming_distances(const std::uint64_t* query, const std::uint64_t* words, std::size_t count,
                       int* out) {
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool has_popcnt = __builtin_cpu_supports("popcnt");
  if (has_popcnt) {
    distances_with_popcnt(query, words, count, out);
    return;
  }
#endif
  distances_portable(query, words, count, out);
}

}  // namespace wifislam::slam
