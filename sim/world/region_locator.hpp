#pragma once
// Which of the plan's regions holds a point, for many points: the answer of regions_find
// (sim/world/plan_queries.hpp) without reading every edge of every ring per point. The free
// space of a large building is one region whose rings have tens of thousands of edges; the
// crossing-number test only needs the edges whose height range holds the point's y, so the edges
// are bucketed in horizontal bands and a query reads one band. The test per edge is
// ring_contains', operation for operation, so the answers are the same. Header-only on the plan's
// types, like wall_face_grid.hpp.

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "sim/world/world_types.hpp"

namespace wifislam::sim::world {

class RegionLocator {
 public:
  /// `band_m` > 0: the height of a band (a long edge is listed in every band it spans).
  explicit RegionLocator(const std::vector<PolygonWithHoles2>& regions, double band_m = 1.0)
      : band_m_(band_m) {
    for (std::size_t r = 0; r < regions.size(); ++r) {
      add_ring(static_cast<int>(r), 0, regions[r].outer);
      for (std::size_t h = 0; h < regions[r].holes.size(); ++h)
        add_ring(static_cast<int>(r), static_cast<int>(h) + 1, regions[r].holes[h]);
    }
  }

  /// Index of the first region holding p (inside its outer ring, in none of its holes), or -1.
  int find(const Eigen::Vector2d& p) const {
    const auto it = bands_.find(band(p.y()));
    if (it == bands_.end()) return -1;
    // Edges come grouped by region, then ring, in order: a ring's parity is complete when the
    // next edge belongs to another ring, a region's answer when it belongs to another region.
    int region = -1, ring = -1;
    bool inside_ring = false, inside_outer = false, inside_hole = false;
    const auto close_ring = [&] {
      if (ring == 0)
        inside_outer = inside_ring;
      else if (inside_ring)
        inside_hole = true;
    };
    for (const Edge& e : it->second) {
      if (e.region != region || e.ring != ring) {
        close_ring();
        if (e.region != region) {
          if (inside_outer && !inside_hole) return region;
          inside_outer = inside_hole = false;
        }
        region = e.region, ring = e.ring, inside_ring = false;
      }
      const Eigen::Vector2d& a = e.a;
      const Eigen::Vector2d& b = e.b;
      if ((a.y() > p.y()) != (b.y() > p.y())) {
        const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
        if (p.x() < x) inside_ring = !inside_ring;
      }
    }
    close_ring();
    return inside_outer && !inside_hole ? region : -1;
  }

 private:
  struct Edge {
    int region, ring;  // ring 0 is the outer one, k the hole k - 1
    Eigen::Vector2d a, b;
  };

  void add_ring(int region, int ring_index, const Polygon2& ring) {
    // The edges as ring_contains walks them: a = ring[i], b = ring[i - 1].
    for (std::size_t i = 0, n = ring.size(), j = n - 1; i < n; j = i++) {
      const Eigen::Vector2d& a = ring[i];
      const Eigen::Vector2d& b = ring[j];
      const std::int64_t b0 = band(std::min(a.y(), b.y())), b1 = band(std::max(a.y(), b.y()));
      for (std::int64_t k = b0; k <= b1; ++k) bands_[k].push_back({region, ring_index, a, b});
    }
  }
  std::int64_t band(double y_m) const {
    return static_cast<std::int64_t>(std::floor(y_m / band_m_));
  }

  double band_m_;
  std::unordered_map<std::int64_t, std::vector<Edge>> bands_;
};

}  // namespace wifislam::sim::world
