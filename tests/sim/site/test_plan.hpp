#pragma once
// A hand-built floor plan: a 30 m x 2 m corridor along x with a row of 4 m rooms to its north.

#include "sim/world/world_types.hpp"

namespace wifislam::test {

inline sim::world::Polygon2 rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

inline sim::world::FloorPlan corridor_with_rooms(int rooms = 7) {
  sim::world::FloorPlan plan;
  const double length = 4.0 * rooms + 2.0;
  plan.walkable.push_back({rectangle(0, 0, length, 2), {}});
  plan.free_space.push_back({rectangle(0, 0, length, 2), {}});
  auto face = [&](double ax, double ay, double bx, double by) {
    sim::world::WallFace2 f;
    f.a_m = {ax, ay};
    f.b_m = {bx, by};
    f.wall_id = static_cast<int>(plan.wall_faces.size());
    plan.wall_faces.push_back(f);
  };
  face(0, 0, length, 0);
  face(length, 2, 0, 2);
  face(0, 2, 0, 0);
  face(length, 0, length, 2);
  for (int i = 0; i < rooms; ++i) {
    sim::world::Room room;
    room.polygon_m = rectangle(4.0 * i + 0.1, 2.15, 4.0 * i + 3.9, 6.0);
    plan.free_space.push_back({room.polygon_m, {}});
    plan.rooms.push_back(room);
    face(4.0 * i + 0.1, 2.15, 4.0 * i + 3.9, 2.15);
    face(4.0 * i + 3.9, 6.0, 4.0 * i + 0.1, 6.0);
  }
  plan.bounds_min_m = {-0.2, -0.2};
  plan.bounds_max_m = {length + 0.2, 6.2};
  return plan;
}

}  // namespace wifislam::test
