#pragma once
// Doors a plan draws (WRLD door polygons, IMDF opening lines) placed on the wall centre lines of
// the partitioned spaces (space_partition.hpp): the drawn door's position is kept, its wall is
// the shared wall nearest it and parallel to it.

#include <optional>

#include <Eigen/Core>

#include "floorplan/imported_plan.hpp"
#include "floorplan/space_partition.hpp"

namespace wifislam::floorplan {

/// A drawn door: its centre, the unit direction along its wall and its width.
struct DoorShape {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero(), axis = Eigen::Vector2d::UnitX();
  double length_m = 0.0;
};

/// A door polygon's shape: the principal axis of its corners and its extent along it.
DoorShape door_shape(const Ring& polygon);
/// An opening line's shape: from its first to its last point.
DoorShape opening_shape(const Ring& line);

/// The door on the shared wall nearest the shape's centre (within 0.6 m) and parallel to its axis
/// (within 25 degrees), as wide as drawn (0.6 to 3 m, at most the wall), centred where drawn;
/// nullopt when no shared wall is that near (an entrance in an outside wall, a door onto stairs).
std::optional<PlacedDoor> door_on_shared_wall(const DoorShape& shape, const Partition& partition,
                                              bool open);

}  // namespace wifislam::floorplan
