#pragma once
// Point queries on the floor plan used to place access points and mask maps: inside a polygon,
// inside free space, clearance from the walls.
//
// Written by hand rather than with CGAL: these are crossing-number and point-segment distance
// tests on a few hundred inexact vertices, where CGAL's exact kernels would only add compile time.

#include <vector>

#include <Eigen/Core>

#include "sim/world/world_types.hpp"

namespace wifislam {

bool point_in_polygon(const Polygon2& polygon, const Eigen::Vector2d& p);
bool point_in_region(const PolygonWithHoles2& region, const Eigen::Vector2d& p);
bool point_in_regions(const std::vector<PolygonWithHoles2>& regions, const Eigen::Vector2d& p);

/// Distance from p to the nearest wall face of the plan (infinity when there is none).
double distance_to_walls_m(const FloorPlan& plan, const Eigen::Vector2d& p);

}  // namespace wifislam
