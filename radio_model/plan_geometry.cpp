#include "radio_model/plan_geometry.hpp"

#include <algorithm>
#include <limits>

namespace wifislam {

bool point_in_polygon(const Polygon2& polygon, const Eigen::Vector2d& p) {
  bool inside = false;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

bool point_in_region(const PolygonWithHoles2& region, const Eigen::Vector2d& p) {
  if (!point_in_polygon(region.outer, p)) return false;
  return std::none_of(region.holes.begin(), region.holes.end(),
                      [&](const Polygon2& hole) { return point_in_polygon(hole, p); });
}

bool point_in_regions(const std::vector<PolygonWithHoles2>& regions, const Eigen::Vector2d& p) {
  return std::any_of(regions.begin(), regions.end(),
                     [&](const PolygonWithHoles2& r) { return point_in_region(r, p); });
}

double distance_to_walls_m(const FloorPlan& plan, const Eigen::Vector2d& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const WallFace2& f : plan.wall_faces) {
    const Eigen::Vector2d ab = f.b_m - f.a_m;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((p - f.a_m).dot(ab) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, (f.a_m + t * ab - p).norm());
  }
  return best;
}

}  // namespace wifislam
