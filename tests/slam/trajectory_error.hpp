#pragma once
// A small aligned trajectory error for the SLAM tests (the full evaluation lives in eval/): poses
// paired by equal timestamps, eval's rigid alignment (eval/alignment.hpp, no scale, as for RGB-D),
// translation RMSE.

#include <map>

#include "core/tum_trajectory.hpp"

namespace wifislam::test {

struct AlignedError {
  double rmse_m = 0.0;
  double max_m = 0.0;
  std::size_t pairs = 0;
};

/// `truth` maps frame timestamps (ns) to ground-truth poses; poses of `estimate` without a match
/// are skipped.
AlignedError aligned_translation_error(const Trajectory& estimate,
                                       const std::map<std::int64_t, Pose>& truth);

}  // namespace wifislam::test
