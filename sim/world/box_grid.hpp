#pragma once
// Items (by index) bucketed by their bounding boxes on a square grid, for "which items can touch
// this box or point?" asked once per item of a large plan. Scanning every item per question is
// quadratic in the size of the building (ten thousand rooms: minutes); a lookup here touches only
// the cells the box covers. Candidates come back sorted and unique, so a loop over them visits the
// items in the order a scan of all of them would: results that depend on order stay the same.
// Header-only on Eigen, like wall_face_grid.hpp.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

namespace wifislam::sim::world {

class BoxGrid {
 public:
  /// `cell_m` > 0: about the size of a typical item or query box.
  explicit BoxGrid(double cell_m) : cell_m_(cell_m) {}

  /// Registers item `index` under every cell its box [lo, hi] covers.
  void add(int index, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
    for_cells(lo, hi, [&](std::int64_t key) { cells_[key].push_back(index); });
  }

  /// The items whose boxes share a cell with [lo, hi]: a superset of those that overlap it.
  std::vector<int> near(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) const {
    std::vector<int> found;
    for_cells(lo, hi, [&](std::int64_t key) {
      const auto it = cells_.find(key);
      if (it != cells_.end()) found.insert(found.end(), it->second.begin(), it->second.end());
    });
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
  }
  std::vector<int> at(const Eigen::Vector2d& p) const { return near(p, p); }

 private:
  template <class Visit>
  void for_cells(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, Visit&& visit) const {
    const std::int64_t x0 = cell(lo.x()), x1 = cell(hi.x()), y0 = cell(lo.y()), y1 = cell(hi.y());
    for (std::int64_t y = y0; y <= y1; ++y)
      for (std::int64_t x = x0; x <= x1; ++x)
        visit(static_cast<std::int64_t>((static_cast<std::uint64_t>(x) << 32) ^
                                        (static_cast<std::uint64_t>(y) & 0xffffffffULL)));
  }
  std::int64_t cell(double coordinate_m) const {
    return static_cast<std::int64_t>(std::floor(coordinate_m / cell_m_));
  }

  double cell_m_;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

}  // namespace wifislam::sim::world
