#pragma once
// Hamming distances between 256-bit binary descriptors (ORB), the inner loop of every exhaustive
// descriptor search: the vocabulary tree's descent and training (slam/bow), and nearest_two for
// the incremental RTAB-Map vocabulary's quantisation and for frame-to-frame matching
// (descriptor_matcher.hpp).

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace wifislam::slam::match {

/// A 32-byte ORB descriptor as four 64-bit words.
using PackedDescriptor = std::array<std::uint64_t, 4>;

inline int hamming_distance(const PackedDescriptor& a, const PackedDescriptor& b) {
  return std::popcount(a[0] ^ b[0]) + std::popcount(a[1] ^ b[1]) + std::popcount(a[2] ^ b[2]) +
         std::popcount(a[3] ^ b[3]);
}

/// The two smallest distances from a query to a set of descriptors, and the first (lowest)
/// index at the smallest: what a scan in index order keeps when it replaces the best only on a
/// strictly smaller distance (ties go to the lower index).
struct NearestTwo {
  int best = std::numeric_limits<int>::max();
  int second = std::numeric_limits<int>::max();
  std::size_t best_index = std::numeric_limits<std::size_t>::max();
};

/// Descriptors stored as four lanes: lanes[k][w] is 64-bit word k of descriptor w. The
/// exhaustive 2-nearest search over them (RTAB-Map's vocabulary quantisation, frame-to-frame
/// matching): AVX-512
/// VPOPCNTDQ eight descriptors at a time where the CPU has it (checked at run time), else popcnt
/// one at a time; the same result either way.
NearestTwo nearest_two(const std::uint64_t* query, const std::uint64_t* const lanes[4],
                       std::size_t count);

}  // namespace wifislam::slam::match
