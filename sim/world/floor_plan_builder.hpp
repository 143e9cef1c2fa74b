#pragma once
// Scene -> FloorPlan: free space, walkable space, wall solids, wall faces, rooms, doors, lights.

#include "sim/scene/scene.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::world {

/// Builds the floor plan with exact polygon booleans (CGAL Polygon_set_2 over an exact kernel),
/// converted to double at the end.
///
/// - Free space is the union of the corridor rectangles (each extended by half its width past
///   both nodes so corners and junctions join), the open areas minus their pillars, the rooms,
///   and the openings of open doors.
/// - Rooms sit beside their corridor behind one wall of `wall_thickness_m`. A room whose
///   rectangle, grown by the wall thickness, would overlap any free space already placed
///   (corridors, open areas, earlier rooms) is dropped whole, so every kept room is a clean
///   rectangle with its door, and a full wall separates it from everything else.
/// - Wall solids are the free space dilated by the wall thickness, minus the free space. The
///   dilation is done per piece in the piece's own frame (corridor and room rectangles grown by
///   the thickness, open areas Minkowski-summed with a square when axis-aligned, else with an
///   octagon), which gives every wall exactly the scene's thickness along corridors of any
///   direction.
/// - Wall faces are the boundary edges of the wall solids, see wall_faces.hpp.
///
/// Throws InvalidInputError when the corridors and open areas do not form one connected piece
/// (only where the robot drives: `robot_space` false for a storey the route is not on, which the
/// radio alone sees), or when the scene's geometry is unusable (degenerate open-area polygon, door
/// not fitting ...).
FloorPlan build_floor_plan(const scene::Scene& scene, bool robot_space = true);

}  // namespace wifislam::sim::world
