#include "eval/association.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>

namespace wifislam::eval {

namespace {
std::int64_t max_difference_ns(double max_difference_s) {
  return static_cast<std::int64_t>(std::llround(max_difference_s * 1e9));
}
}  // namespace

std::vector<AssociatedIndices> associate_by_time(const std::vector<Timestamp>& first,
                                                 const std::vector<Timestamp>& second,
                                                 double max_difference_s,
                                                 std::int64_t second_offset_ns) {
  const std::int64_t max_ns = max_difference_ns(max_difference_s);
  // A repeated stamp is one dict key in associate.py, holding its last line.
  auto last_of_stamp = [](const std::vector<Timestamp>& list, std::size_t i) {
    return i + 1 == list.size() || list[i + 1].ns != list[i].ns;
  };
  // Candidates (|dt|, a, b): both lists are sorted, so each a only looks at a window of b.
  // Index order is stamp order, so sorting by index breaks ties as associate.py's tuple sort.
  std::vector<std::tuple<std::int64_t, std::size_t, std::size_t>> candidates;
  std::size_t window_start = 0;
  for (std::size_t a = 0; a < first.size(); ++a) {
    while (window_start < second.size() &&
           second[window_start].ns + second_offset_ns <= first[a].ns - max_ns) {
      ++window_start;
    }
    if (!last_of_stamp(first, a)) continue;
    for (std::size_t b = window_start;
         b < second.size() && second[b].ns + second_offset_ns < first[a].ns + max_ns; ++b) {
      if (!last_of_stamp(second, b)) continue;
      candidates.emplace_back(std::abs(first[a].ns - (second[b].ns + second_offset_ns)), a, b);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<char> used_first(first.size(), 0), used_second(second.size(), 0);
  std::vector<AssociatedIndices> matches;
  for (const auto& [dt, a, b] : candidates) {
    if (used_first[a] || used_second[b]) continue;
    used_first[a] = used_second[b] = 1;
    matches.push_back({a, b});
  }
  std::sort(matches.begin(), matches.end(),
            [](const AssociatedIndices& x, const AssociatedIndices& y) {
              return std::tie(x.first, x.second) < std::tie(y.first, y.second);
            });
  return matches;
}

std::optional<std::size_t> nearest_stamp(const std::vector<Timestamp>& sorted, Timestamp t,
                                         double max_difference_s) {
  const std::int64_t max_ns = max_difference_ns(max_difference_s);
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), t);
  std::optional<std::size_t> best;
  std::int64_t best_dt = max_ns;
  auto consider = [&](std::vector<Timestamp>::const_iterator c) {
    const std::int64_t dt = std::abs(c->ns - t.ns);
    if (dt < best_dt) best_dt = dt, best = static_cast<std::size_t>(c - sorted.begin());
  };
  if (it != sorted.end()) consider(it);
  if (it != sorted.begin()) consider(std::prev(it));
  return best;
}

}  // namespace wifislam::eval
