#pragma once
// Access points for the radio tests: a row along x at 2.5 m, each with both radios and three
// BSSIDs per radio, MACs and channels from `seed`.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "radio_model/access_point.hpp"

namespace wifislam::test {

inline std::vector<radio_model::AccessPoint> aps_along_x(int count, std::uint64_t seed,
                                                         double spacing_m = 10.0) {
  radio_model::MacAllocator macs(seed);
  std::vector<radio_model::AccessPoint> aps;
  for (int i = 0; i < count; ++i)
    aps.push_back(radio_model::make_access_point(i, Eigen::Vector3d(spacing_m * i, 3.0, 2.5), 20.0,
                                                 3, seed, macs));
  return aps;
}

}  // namespace wifislam::test
