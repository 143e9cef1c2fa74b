#pragma once
// Pairing two trajectories by timestamp with the rule of the TUM RGB-D tools (associate.py, used
// by evaluate_ate.py with the ground truth as the first list and the estimate as the second):
//   - a stamp repeated in one list counts once, with its last line (associate.py reads each file
//     into a dict keyed by stamp); the trajectory readers refuse such a file at the repeated
//     line (core/tum_trajectory.hpp), so only lists built in memory reach this rule;
//   - every pair with |first - (second + offset)| < max_difference (strictly) is a candidate;
//   - candidates are sorted by (|difference|, first stamp, second stamp) and taken greedily,
//     each stamp used at most once, so an exact half-way tie goes to the earlier stamp of the
//     first list, then of the second;
//   - the result is sorted by the first list's time.
// One difference: stamps and differences are compared exactly in integer nanoseconds, where
// associate.py subtracts floating-point seconds (there, two differences equal on paper can
// differ in the last bit and break a tie the other way).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/timestamp.hpp"

namespace wifislam::eval {

struct AssociatedIndices {
  std::size_t first = 0, second = 0;
  friend bool operator==(const AssociatedIndices&, const AssociatedIndices&) = default;
};

/// Both lists sorted by time (non-decreasing), as read_tum_trajectory guarantees.
/// `second_offset_ns` is added to every stamp of `second` (evaluate_ate.py --offset).
std::vector<AssociatedIndices> associate_by_time(const std::vector<Timestamp>& first,
                                                 const std::vector<Timestamp>& second,
                                                 double max_difference_s,
                                                 std::int64_t second_offset_ns = 0);

/// Index of the stamp of `sorted` nearest to `t`, if closer than `max_difference_s`.
std::optional<std::size_t> nearest_stamp(const std::vector<Timestamp>& sorted, Timestamp t,
                                         double max_difference_s);

}  // namespace wifislam::eval
