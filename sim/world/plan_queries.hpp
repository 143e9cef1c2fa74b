#pragma once
// Point and area queries on the plan's double-precision polygons: inside free space, distance to
// the nearest wall, areas. Used by the route check, the tests and the plan drawing.

#include <vector>

#include <Eigen/Core>

#include "sim/world/world_types.hpp"

namespace wifislam::sim::world {

/// Signed area (positive for counter-clockwise rings).
double ring_signed_area_m2(const Polygon2& ring);
/// Area of the regions (outer rings minus holes).
double regions_area_m2(const std::vector<PolygonWithHoles2>& regions);

/// Crossing-number test; points exactly on the boundary may go either way.
bool ring_contains(const Polygon2& ring, const Eigen::Vector2d& p);
bool region_contains(const PolygonWithHoles2& region, const Eigen::Vector2d& p);
/// Index of the region containing p, or -1.
int regions_find(const std::vector<PolygonWithHoles2>& regions, const Eigen::Vector2d& p);
inline bool regions_contain(const std::vector<PolygonWithHoles2>& regions,
                            const Eigen::Vector2d& p) {
  return regions_find(regions, p) >= 0;
}

double segment_distance_m(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                          const Eigen::Vector2d& b);
/// Distance from p to the nearest wall face (infinity when the plan has none); `nearest_face`
/// receives that face's index when not null.
double nearest_wall_distance_m(const FloorPlan& plan, const Eigen::Vector2d& p,
                               int* nearest_face = nullptr);

}  // namespace wifislam::sim::world
