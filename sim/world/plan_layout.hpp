#pragma once
// The scene's building blocks as oriented rectangles, before any polygon booleans: corridor
// rectangles, candidate rooms and their door openings. Pure arithmetic; the floor-plan builder
// turns these into exact CGAL polygons and decides which rooms fit.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "sim/scene/scene.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::world {

/// A rectangle in a corridor's own frame: points origin + s * along + l * left for s in
/// [s0, s1] and l in [l0, l1]. `left` is `along` turned by +90 degrees.
struct OrientedRect {
  Eigen::Vector2d origin_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d along = Eigen::Vector2d::UnitX();
  double s0 = 0, s1 = 0, l0 = 0, l1 = 0;

  Eigen::Vector2d left() const { return {-along.y(), along.x()}; }
  Eigen::Vector2d point(double s, double l) const { return origin_m + s * along + l * left(); }
  /// Corners counter-clockwise: (s0,l0) (s1,l0) (s1,l1) (s0,l1).
  Polygon2 corners() const;
  /// The same rectangle grown by `margin_m` on every side.
  OrientedRect grown(double margin_m) const;
  /// Frame coordinates (s, l) of a world point.
  Eigen::Vector2d to_frame(const Eigen::Vector2d& p) const;
  bool contains(const Eigen::Vector2d& p, double tolerance_m = 0.0) const;
  Eigen::Vector2d center() const { return point(0.5 * (s0 + s1), 0.5 * (l0 + l1)); }
};

struct CorridorLayout {
  int corridor_index = -1;
  double length_m = 0;
  OrientedRect rect;  // extended by width/2 past each node so corners and junctions join
};

/// A room that the scene asks for; the floor-plan builder keeps it only if it fits.
struct RoomCandidate {
  int corridor_index = -1;
  int row_index = -1;
  OrientedRect room;  // free space of the room
  OrientedRect door;  // the opening through the wall between corridor and room
  double door_width_m = 0.9;
  bool door_open = false;
  radio_model::WallMaterial material = radio_model::WallMaterial::kBrick;
};

struct PlanLayout {
  std::vector<CorridorLayout> corridors;
  std::vector<RoomCandidate> rooms;
};

/// A space door's opening: along the door from its `from_m` jamb, `wall_thickness_m` to either
/// side of its centre line (deeper than the wall, so it overlaps the spaces on both sides).
OrientedRect space_door_rect(const scene::SpaceDoor& door, double wall_thickness_m);

/// Lays out corridors and candidate rooms. Throws InvalidInputError for a corridor that names a
/// missing node or has zero length, or a room row whose door does not fit in its rooms.
PlanLayout lay_out_scene(const scene::Scene& scene);

}  // namespace wifislam::sim::world
