#pragma once
// The importers keep a drawing's pillars and wall islands as obstacles where they were drawn,
// while the partition (space_partition.hpp) moves each space's outline: gaps close, spaces shrink
// by half a wall and are simplified. An island drawn close to a wall can then cut a strip off the
// space between itself and the wall: free space no robot can reach, which splits the walkable
// space in two (and the world builder refuses a robot's space in pieces). Westport House's
// floor 1 has one, 1.5 cm wide and 3.8 m long.
//
// A part that an obstacle cuts off a piece and that is smaller than the partition's min_area_m2
// (the size below which the partition itself drops slivers) becomes part of that obstacle: in the
// building, the island meets the wall there. Larger parts are real: the space is split, and the
// caller treats it as a space split by the wall thickness.

#include <vector>

#include "floorplan/geos_geometry.hpp"
#include "floorplan/space_partition.hpp"
#include "sim/scene/scene.hpp"

namespace wifislam::floorplan {

struct ObstacleCuts {
  /// For each partition piece, the free parts of at least min_area_m2 the obstacles leave of it
  /// (1 where they divide nothing; the largest part counts even when it is smaller).
  std::vector<int> parts_per_piece;
  int strips_made_solid = 0;
};

/// Grows `obstacles` over the strips they cut off the partition's pieces (see above). Obstacles
/// that are not valid polygons are left alone: the world builder names them.
ObstacleCuts make_cut_off_strips_solid(const GeosContext& geos, const Partition& partition,
                                       double min_area_m2,
                                       std::vector<sim::scene::Obstacle>& obstacles);

}  // namespace wifislam::floorplan
