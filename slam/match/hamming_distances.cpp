#include "slam/match/hamming_distances.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

namespace wifislam::slam::match {

namespace {

/// The scan's step for one more descriptor at distance `d` and index `w`.
inline void keep_nearest_two(NearestTwo& r, int d, std::size_t w) {
  if (d < r.best) {
    r.second = r.best;
    r.best = d;
    r.best_index = w;
  } else if (d < r.second) {
    r.second = d;
  }
}

/// One descriptor at a time from `begin`, continuing `r`. GCC builds it twice (with the popcnt
/// instruction and without) and picks one when the program starts.
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target_clones("popcnt", "default")))
#endif
NearestTwo
nearest_two_scalar(const std::uint64_t* query, const std::uint64_t* const lanes[4],
                   std::size_t begin, std::size_t count, NearestTwo r) {
  for (std::size_t w = begin; w < count; ++w) {
    keep_nearest_two(r,
                     std::popcount(query[0] ^ lanes[0][w]) + std::popcount(query[1] ^ lanes[1][w]) +
                         std::popcount(query[2] ^ lanes[2][w]) +
                         std::popcount(query[3] ^ lanes[3][w]),
                     w);
  }
  return r;
}

#if defined(__x86_64__) && defined(__GNUC__)
/// Eight descriptors at a time: their distances in one register; only the lanes that would
/// change the result (distance below the current second) go through the scalar step, in index
/// order, so the result is the scan's.
__attribute__((target("avx512f,avx512vpopcntdq,popcnt"))) NearestTwo nearest_two_avx512(
    const std::uint64_t* query, const std::uint64_t* const lanes[4], std::size_t count) {
  const __m512i q0 = _mm512_set1_epi64(static_cast<long long>(query[0]));
  const __m512i q1 = _mm512_set1_epi64(static_cast<long long>(query[1]));
  const __m512i q2 = _mm512_set1_epi64(static_cast<long long>(query[2]));
  const __m512i q3 = _mm512_set1_epi64(static_cast<long long>(query[3]));
  NearestTwo r;
  std::size_t w = 0;
  alignas(64) long long d[8];
  for (; w + 8 <= count; w += 8) {
    const __m512i x0 = _mm512_xor_si512(_mm512_loadu_si512(lanes[0] + w), q0);
    const __m512i x1 = _mm512_xor_si512(_mm512_loadu_si512(lanes[1] + w), q1);
    const __m512i x2 = _mm512_xor_si512(_mm512_loadu_si512(lanes[2] + w), q2);
    const __m512i x3 = _mm512_xor_si512(_mm512_loadu_si512(lanes[3] + w), q3);
    const __m512i dist =
        _mm512_add_epi64(_mm512_add_epi64(_mm512_popcnt_epi64(x0), _mm512_popcnt_epi64(x1)),
                         _mm512_add_epi64(_mm512_popcnt_epi64(x2), _mm512_popcnt_epi64(x3)));
    const __mmask8 below = _mm512_cmplt_epi64_mask(dist, _mm512_set1_epi64(r.second));
    if (below == 0) continue;
    _mm512_store_si512(d, dist);
    for (int j = 0; j < 8; ++j) keep_nearest_two(r, static_cast<int>(d[j]), w + j);
  }
  return nearest_two_scalar(query, lanes, w, count, r);
}
#endif

}  // namespace

NearestTwo nearest_two(const std::uint64_t* query, const std::uint64_t* const lanes[4],
                       std::size_t count) {
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool has_avx512 =
      __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vpopcntdq");
  if (has_avx512) return nearest_two_avx512(query, lanes, count);
#endif
  return nearest_two_scalar(query, lanes, 0, count, {});
}

}  // namespace wifislam::slam::match
