// Hand-written rather than CGAL: the plan is stored in double Eigen vectors and these queries run
// thousands of times (route samples, tests); CGAL's bounded_side_2 would need a kernel copy of
// every ring per query and adds nothing to a crossing-number test on inexact data.
#include "sim/world/plan_queries.hpp"

#include <algorithm>
#include <limits>

namespace wifislam::sim::world {

double ring_signed_area_m2(const Polygon2& ring) {
  double twice = 0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Eigen::Vector2d& a = ring[i];
    const Eigen::Vector2d& b = ring[(i + 1) % n];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice;
}

double regions_area_m2(const std::vector<PolygonWithHoles2>& regions) {
  double area = 0;
  for (const auto& r : regions) {
    area += std::abs(ring_signed_area_m2(r.outer));
    for (const auto& h : r.holes) area -= std::abs(ring_signed_area_m2(h));
  }
  return area;
}

bool ring_contains(const Polygon2& ring, const Eigen::Vector2d& p) {
  bool inside = false;
  for (std::size_t i = 0, n = ring.size(), j = n - 1; i < n; j = i++) {
    const Eigen::Vector2d& a = ring[i];
    const Eigen::Vector2d& b = ring[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

bool region_contains(const PolygonWithHoles2& region, const Eigen::Vector2d& p) {
  if (!ring_contains(region.outer, p)) return false;
  for (const auto& h : region.holes)
    if (ring_contains(h, p)) return false;
  return true;
}

int regions_find(const std::vector<PolygonWithHoles2>& regions, const Eigen::Vector2d& p) {
  for (std::size_t i = 0; i < regions.size(); ++i)
    if (region_contains(regions[i], p)) return static_cast<int>(i);
  return -1;
}

double segment_distance_m(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                          const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

double nearest_wall_distance_m(const FloorPlan& plan, const Eigen::Vector2d& p, int* nearest_face) {
  double best = std::numeric_limits<double>::infinity();
  int best_index = -1;
  for (std::size_t i = 0; i < plan.wall_faces.size(); ++i) {
    const double d = segment_distance_m(p, plan.wall_faces[i].a_m, plan.wall_faces[i].b_m);
    if (d < best) best = d, best_index = static_cast<int>(i);
  }
  if (nearest_face != nullptr) *nearest_face = best_index;
  return best;
}

}  // namespace wifislam::sim::world
