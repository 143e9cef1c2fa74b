#pragma once
// The importers keep a drawing's pillars and wall islands as obstacles where they were drawn,
// while the partition (space_partition.hpp) moves each space's outline: gaps close, spaces shrink
// by half a wall and are simplified. An island drawn close to a wall can then cut a strip off the
// space between itself and the wall: free space no robot can reach, which splits the walkable
// space in two (and the world builder refuses a robot's space in pieces). Westport House's
// floor 1 has one, 1.5 cm wide and 3.8 m long.
//
// A part an obstacle cuts off a piece that is smaller than the partition's min_area_m2 (the size
// below which the partition itself drops slivers) or narrower than a wall becomes part of that
// obstacle: in the building, the island meets the wall there. Larger parts are left as they are:
// the world builder joins the walkable spaces and their doorways, so a space an obstacle divides
// may still be one walkable piece through its doors (and when it is not, the builder says so).

#include <vector>

#include "floorplan/geos_geometry.hpp"
#include "floorplan/space_partition.hpp"
#include "sim/scene/scene.hpp"

namespace wifislam::floorplan {

/// Grows `obstacles` over the strips they cut off the partition's pieces (see above); returns how
/// many strips were made solid. Obstacles that are not valid polygons are left alone: the world
/// builder names them.
int make_cut_off_strips_solid(const GeosContext& geos, const Partition& partition,
                              double min_area_m2, double wall_thickness_m,
                              std::vector<sim::scene::Obstacle>& obstacles);

}  // namespace wifislam::floorplan
