#pragma once
// Turns a floor plan's room and corridor polygons, as drawn (touching, overlapping or a little
// apart), into spaces that lie exactly one wall thickness apart, which is what a scene's walls
// are grown from (sim/scene/scene.hpp, Space). The steps, in metres:
//
//  1. The building's footprint: the union of all polygons, closed morphologically by
//     `gap_close_m` (grown, then shrunk back with mitred joins), so that gaps narrower than
//     2 x gap_close_m between drawn spaces (the walls the drawing left out) are inside the
//     building while its outline stays where it was drawn.
//  2. Each space grows by gap_close_m, clipped to the footprint and to the spaces placed before
//     it (corridors first, then areas, then rooms; larger first within a kind): neighbours now
//     touch along the centre lines of the walls between them.
//  3. Each space shrinks by half a wall thickness (mitred), leaving a wall of exactly the
//     thickness between neighbours, and is snapped to a 1 mm grid.
//
// The shared boundaries of step 2 are the wall centre lines; doors are placed on them.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "floorplan/geos_geometry.hpp"
#include "sim/scene/scene.hpp"

namespace wifislam::floorplan {

struct SpaceInput {
  std::string id, name;
  sim::scene::SpaceKind kind = sim::scene::SpaceKind::kRoom;
  radio_model::WallMaterial material = radio_model::WallMaterial::kBrick;
  PolygonRings polygon_m;
};

struct PartitionOptions {
  double wall_thickness_m = 0.15;
  /// Gaps up to twice this between drawn spaces become wall; wider ones stay outside.
  double gap_close_m = 0.6;
  /// Pieces smaller than this after step 3 are dropped (slivers between drawn polygons).
  double min_area_m2 = 0.5;
};

/// One free piece of a space after step 3 (a space may split into several).
struct SpacePiece {
  int input = -1;  // index into the inputs
  PolygonRings free_m;
};

/// A straight piece of wall centre line between the grown spaces `a` and `b` (input indices).
struct SharedWall {
  int a = -1, b = -1;
  Eigen::Vector2d from_m = Eigen::Vector2d::Zero(), to_m = Eigen::Vector2d::Zero();
  double length_m() const { return (to_m - from_m).norm(); }
};

struct Partition {
  std::vector<SpacePiece> pieces;
  std::vector<SharedWall> shared_walls;
  /// Inputs that kept no piece (covered by earlier spaces or too small), by index.
  std::vector<int> dropped;
};

Partition partition_spaces(const GeosContext& geos, const std::vector<SpaceInput>& inputs,
                           const PartitionOptions& options);

}  // namespace wifislam::floorplan
