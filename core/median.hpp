#pragma once
// The median of a list of numbers: the middle value, or the mean of the two middle values of an
// even count (as numpy.median); 0 for an empty list. The one median every report uses.

#include <algorithm>
#include <vector>

namespace wifislam {

inline double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t mid = values.size() / 2;
  return values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

}  // namespace wifislam
