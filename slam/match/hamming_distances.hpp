#pragma once
// Hamming distances between 256-bit binary descriptors (ORB), the inner loop of every exhaustive
// descriptor search: the incremental RTAB-Map vocabulary's quantisation and the vocabulary tree's
// descent and training (slam/bow).

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

namespace wifislam::slam {

/// A 32-byte ORB descriptor as four 64-bit words.
using PackedDescriptor = std::array<std::uint64_t, 4>;

inline int hamming_distance(const PackedDescriptor& a, const PackedDescriptor& b) {
  return std::popcount(a[0] ^ b[0]) + std::popcount(a[1] ^ b[1]) + std::popcount(a[2] ^ b[2]) +
         std::popcount(a[3] ^ b[3]);
}

/// Distances of one descriptor (4 x 64 bits) to `count` consecutive descriptors in `words`
/// (4 x 64 bits each) into `out`. Uses the popcnt instruction where the CPU has it (checked at
/// run time); the same integers either way.
void hamming_distances(const std::uint64_t* query, const std::uint64_t* words, std::size_t count,
                       int* out);

}  // namespace wifislam::slam
