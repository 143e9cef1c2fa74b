#pragma once
// A route through an imported plan's walkable space, for scenes whose plan has no corridor graph:
// a closed tour over points spread along the corridors (or the plan's navigation paths, or the
// user's waypoints), walked `laps` times so that SLAM sees every place again.
//
// On a 0.1 m grid of the walkable space: clearance to the nearest non-walkable cell (OpenCV's
// exact Euclidean distance transform); cells with at least `clearance_m` form the robot's space
// (its largest 8-connected piece). Targets: the given points snapped to that space, else
// farthest-point sampling of it until every cell is within `target_spacing_m` of a target.
// Order: nearest neighbour by walking distance from the first target, improved by 2-opt. Legs:
// Dijkstra with a cost that prefers the middle of corridors, then shortcut while the straight
// segment keeps the clearance.

#include <vector>

#include <Eigen/Core>

#include "sim/world/world_types.hpp"

namespace wifislam::floorplan {

struct TourOptions {
  double clearance_m = 0.6;       // grid error, corner rounding: the route builder checks 0.3 m
  double target_spacing_m = 8.0;  // farthest-point sampling stops below this
  int laps = 2;
  double cell_m = 0.1;
};

/// Waypoints of the tour (first = last). `must_visit` may be empty; with `keep_order` its points
/// are visited in the order given (the user's route), else in the planned tour order (a plan's
/// navigation paths). Throws InvalidInputError when the walkable space has no room for the robot
/// at that clearance.
std::vector<Eigen::Vector2d> plan_tour(const sim::world::FloorPlan& plan,
                                       const std::vector<Eigen::Vector2d>& must_visit,
                                       const TourOptions& options, bool keep_order);

}  // namespace wifislam::floorplan
