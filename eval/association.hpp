#pragma once
// Pairing two trajectories by timestamp, exactly as the TUM RGB-D tools do (associate.py, used by
// evaluate_ate.py): every pair of stamps closer than `max_difference_s` (strictly) is a candidate;
// candidates are taken greedily from the smallest |dt|, each stamp used at most once; the result
// is sorted by the first trajectory's time. Stamps are compared in integer nanoseconds.

#include <cstddef>
#include <optional>
#include <vector>

#include "core/timestamp.hpp"

namespace wifislam::eval {

struct AssociatedIndices {
  std::size_t first = 0, second = 0;
  friend bool operator==(const AssociatedIndices&, const AssociatedIndices&) = default;
};

/// Both lists sorted by time (non-decreasing), as read_tum_trajectory guarantees.
std::vector<AssociatedIndices> associate_by_time(const std::vector<Timestamp>& first,
                                                 const std::vector<Timestamp>& second,
                                                 double max_difference_s);

/// Index of the stamp of `sorted` nearest to `t`, if closer than `max_difference_s`.
std::optional<std::size_t> nearest_stamp(const std::vector<Timestamp>& sorted, Timestamp t,
                                         double max_difference_s);

}  // namespace wifislam::eval
