#include "slam/bow/bow_feature_matcher.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "slam/match/packed_descriptor.hpp"

namespace wifislam::slam::bow {

std::vector<match::PackedDescriptor> pack_descriptors(const cv::Mat& descriptors) {
  std::vector<match::PackedDescriptor> out(static_cast<std::size_t>(descriptors.rows));
  for (int r = 0; r < descriptors.rows; ++r) out[r] = match::packed_descriptor(descriptors, r);
  return out;
}

int count_bow_matches(const BowKeyframe& a, const BowKeyframe& b, const BowMatchOptions& options) {
  constexpr int kBins = 30;
  std::vector<std::uint8_t> b_taken(b.descriptors.size(), 0);
  std::array<std::vector<int>, kBins> rotation_bins;  // match angle differences
  int matches = 0;
  auto ia = a.direct_index.begin();
  auto ib = b.direct_index.begin();
  // Both direct indexes are sorted by node: walk them together (ORB-SLAM2 does the same).
  while (ia != a.direct_index.end() && ib != b.direct_index.end()) {
    if (ia->first < ib->first) {
      ++ia;
      continue;
    }
    if (ib->first < ia->first) {
      ++ib;
      continue;
    }
    for (int fa : ia->second) {
      int best = std::numeric_limits<int>::max(), second = std::numeric_limits<int>::max();
      int best_b = -1;
      for (int fb : ib->second) {
        if (b_taken[static_cast<std::size_t>(fb)]) continue;
        const int d = match::hamming_distance(a.descriptors[static_cast<std::size_t>(fa)],
                                              b.descriptors[static_cast<std::size_t>(fb)]);
        if (d < best) {
          second = best;
          best = d;
          best_b = fb;
        } else if (d < second) {
          second = d;
        }
      }
      if (best_b < 0 || best > options.max_distance ||
          !(static_cast<double>(best) < options.ratio * static_cast<double>(second))) {
        continue;
      }
      b_taken[static_cast<std::size_t>(best_b)] = 1;
      ++matches;
      if (options.check_orientation) {
        float rot = a.angles_deg[static_cast<std::size_t>(fa)] -
                    b.angles_deg[static_cast<std::size_t>(best_b)];
        if (rot < 0.0f) rot += 360.0f;
        int bin = static_cast<int>(std::round(rot * (1.0f / 360.0f) * kBins));
        if (bin == kBins) bin = 0;
        rotation_bins[static_cast<std::size_t>(std::clamp(bin, 0, kBins - 1))].push_back(best_b);
      }
    }
    ++ia;
    ++ib;
  }
  if (!options.check_orientation || matches == 0) return matches;

  // ComputeThreeMaxima: keep the three fullest bins; the second and third only when they hold at
  // least a tenth of the first.
  std::array<std::size_t, 3> top{0, 0, 0};
  std::array<int, 3> top_bin{-1, -1, -1};
  for (int i = 0; i < kBins; ++i) {
    const std::size_t n = rotation_bins[static_cast<std::size_t>(i)].size();
    if (n > top[0]) {
      top = {n, top[0], top[1]};
      top_bin = {i, top_bin[0], top_bin[1]};
    } else if (n > top[1]) {
      top = {top[0], n, top[1]};
      top_bin = {top_bin[0], i, top_bin[1]};
    } else if (n > top[2]) {
      top[2] = n;
      top_bin[2] = i;
    }
  }
  int kept = static_cast<int>(top[0]);
  if (static_cast<double>(top[1]) >= 0.1 * static_cast<double>(top[0])) {
    kept += static_cast<int>(top[1]);
    if (static_cast<double>(top[2]) >= 0.1 * static_cast<double>(top[0])) {
      kept += static_cast<int>(top[2]);
    }
  }
  return kept;
}

}  // namespace wifislam::slam::bow
