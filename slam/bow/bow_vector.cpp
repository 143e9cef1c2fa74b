#include "slam/bow/bow_vector.hpp"

#include <algorithm>
#include <cmath>

namespace wifislam::slam::bow {

void l1_normalise(BowVector& v) {
  double norm = 0.0;
  for (const auto& [word, weight] : v) norm += std::abs(weight);
  if (norm <= 0.0) return;
  for (auto& [word, weight] : v) weight /= norm;
}

double l1_score(const BowVector& a, const BowVector& b) {
  // Over the common words only, as DBoW2's L1Scoring: |x - y| - |x| - |y| is 0 where one is 0,
  // so 1 - 1/2 sum |a - b| = -1/2 sum over common words of (|x - y| - |x| - |y|).
  double sum = 0.0;
  auto i = a.begin();
  auto j = b.begin();
  while (i != a.end() && j != b.end()) {
    if (i->first < j->first) {
      ++i;
    } else if (j->first < i->first) {
      ++j;
    } else {
      const double x = i->second, y = j->second;
      sum += std::abs(x - y) - std::abs(x) - std::abs(y);
      ++i;
      ++j;
    }
  }
  return std::clamp(-0.5 * sum, 0.0, 1.0);
}

}  // namespace wifislam::slam::bow
