#pragma once
// The plan's wall faces bucketed on a square grid, for "is a wall closer than r?" asked at many
// points (every route sample, every AP candidate spot). Scanning every face per point is
// quadratic in the size of the building (minutes for a 20 km corridor); a lookup here touches
// only the faces near the point. Header-only on the plan's types, so the radio model, which
// uses the world's types but not its generator library, can use it too.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "sim/world/world_types.hpp"

namespace wifislam::sim::world {

class WallFaceGrid {
 public:
  /// Answers queries with radius up to `max_radius_m` (> 0, finite). Memory grows with the total
  /// wall length: about 25 entries per cell side (max(radius, 1 m)) of wall.
  WallFaceGrid(const FloorPlan& plan, double max_radius_m)
      : plan_(plan), cell_m_(std::max(max_radius_m, 1.0)) {
    if (!(max_radius_m > 0.0 && std::isfinite(max_radius_m))) {
      throw std::invalid_argument("WallFaceGrid: the radius must be positive and finite");
    }
    // Each face is sampled every cell side at most and registered in the 5 x 5 cells around
    // every sample: a point p closer than a cell side to the face has its nearest face point
    // within half a side of a sample s, so |p - s| < 1.5 sides and p's cell is within two cells
    // of s's.
    for (std::size_t i = 0; i < plan.wall_faces.size(); ++i) {
      const Eigen::Vector2d a = plan.wall_faces[i].a_m, b = plan.wall_faces[i].b_m;
      const int steps = static_cast<int>(std::ceil((b - a).norm() / cell_m_));
      for (int k = 0; k <= steps; ++k) {
        const Eigen::Vector2d s = steps > 0 ? Eigen::Vector2d(a + (b - a) * k / steps) : a;
        const std::int64_t cx = cell(s.x()), cy = cell(s.y());
        for (std::int64_t dy = -2; dy <= 2; ++dy) {
          for (std::int64_t dx = -2; dx <= 2; ++dx) {
            std::vector<int>& faces = cells_[key(cx + dx, cy + dy)];
            if (faces.empty() || faces.back() != static_cast<int>(i)) {
              faces.push_back(static_cast<int>(i));
            }
          }
        }
      }
    }
  }

  /// The distance from p to the nearest wall face when it is less than `radius_m` (at most the
  /// grid's max radius), else infinity. Exact below the radius: the same value as
  /// nearest_wall_distance_m (sim/world/plan_queries.hpp) there.
  double nearest_within_m(const Eigen::Vector2d& p, double radius_m) const {
    double best = std::numeric_limits<double>::infinity();
    const auto it = cells_.find(key(cell(p.x()), cell(p.y())));
    if (it == cells_.end()) return best;
    for (const int i : it->second) {
      // As segment_distance_m, operation for operation.
      const Eigen::Vector2d& a = plan_.wall_faces[i].a_m;
      const Eigen::Vector2d ab = plan_.wall_faces[i].b_m - a;
      const double len2 = ab.squaredNorm();
      const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
      best = std::min(best, (a + t * ab - p).norm());
    }
    return best < std::min(radius_m, cell_m_) ? best : std::numeric_limits<double>::infinity();
  }

 private:
  std::int64_t cell(double coordinate_m) const {
    return static_cast<std::int64_t>(std::floor(coordinate_m / cell_m_));
  }
  static std::int64_t key(std::int64_t cx, std::int64_t cy) {
    return static_cast<std::int64_t>((static_cast<std::uint64_t>(cx) << 32) ^
                                     (static_cast<std::uint64_t>(cy) & 0xffffffffULL));
  }

  const FloorPlan& plan_;
  double cell_m_ = 1.0;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

}  // namespace wifislam::sim::world
