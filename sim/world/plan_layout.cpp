#include "sim/world/plan_layout.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"

namespace wifislam::sim::world {

Polygon2 OrientedRect::corners() const {
  return {point(s0, l0), point(s1, l0), point(s1, l1), point(s0, l1)};
}

OrientedRect OrientedRect::grown(double margin_m) const {
  OrientedRect r = *this;
  r.s0 -= margin_m;
  r.s1 += margin_m;
  r.l0 -= margin_m;
  r.l1 += margin_m;
  return r;
}

Eigen::Vector2d OrientedRect::to_frame(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d d = p - origin_m;
  return {d.dot(along), d.dot(left())};
}

bool OrientedRect::contains(const Eigen::Vector2d& p, double tolerance_m) const {
  const Eigen::Vector2d f = to_frame(p);
  return f.x() >= s0 - tolerance_m && f.x() <= s1 + tolerance_m && f.y() >= l0 - tolerance_m &&
         f.y() <= l1 + tolerance_m;
}

namespace {

void lay_out_room_row(const scene::Scene& scene, const CorridorLayout& corridor, int row_index,
                      double side_sign, PlanLayout& layout) {
  const scene::Corridor& c = scene.corridors[corridor.corridor_index];
  const scene::RoomRow& row = c.rooms[row_index];
  const double t = scene.building.wall_thickness_m;
  const double half_w = 0.5 * c.width_m;
  const double from = row.from_m;
  const double to = row.to_m.value_or(corridor.length_m);
  const std::string where = fmt::format("corridor '{}' rooms[{}]", c.id, row_index);
  if (row.room_length_m <= t || row.depth_m <= 0 || to <= from)
    throw InvalidInputError(where +
                            ": rooms need room_length_m > wall thickness, depth_m > 0 "
                            "and to_m > from_m");
  // Rooms are `room_length_m` long centre to centre of their partition walls; the last one takes
  // the remainder when that is at least half a room.
  std::vector<std::pair<double, double>> spans;
  for (double start = from; start < to - 1e-9;) {
    double end = start + row.room_length_m;
    if (end > to + 1e-9) {
      if (to - start < 0.5 * row.room_length_m) break;
      end = to;
    }
    spans.emplace_back(start, end);
    start = end;
  }
  // The lateral range on the chosen side: a wall of thickness t separates room and corridor.
  const double near_l = half_w, wall_l = half_w + t, far_l = half_w + t + row.depth_m;
  for (const auto& [start, end] : spans) {
    RoomCandidate room;
    room.corridor_index = corridor.corridor_index;
    room.row_index = row_index;
    room.material = row.material;
    room.door_open = row.doors_open;
    room.door_width_m = row.door_width_m;
    room.room = corridor.rect;
    room.room.s0 = start + 0.5 * t;
    room.room.s1 = end - 0.5 * t;
    // A door that would run past the room's end (the shorter last room of a row) slides back
    // until it fits.
    if (row.door_width_m <= 0 || row.door_width_m > room.room.s1 - room.room.s0 + 1e-9)
      throw InvalidInputError(fmt::format("{}: a door {} m wide does not fit in a room {} m long",
                                          where, row.door_width_m, end - start));
    const double door_s0 =
        std::clamp(start + row.door_offset_m, room.room.s0, room.room.s1 - row.door_width_m);
    const double door_s1 = door_s0 + row.door_width_m;
    room.door = corridor.rect;
    room.door.s0 = door_s0;
    room.door.s1 = door_s1;
    if (side_sign > 0) {
      room.room.l0 = wall_l, room.room.l1 = far_l;
      room.door.l0 = near_l, room.door.l1 = wall_l;
    } else {
      room.room.l0 = -far_l, room.room.l1 = -wall_l;
      room.door.l0 = -wall_l, room.door.l1 = -near_l;
    }
    layout.rooms.push_back(room);
  }
}

}  // namespace

PlanLayout lay_out_scene(const scene::Scene& scene) {
  PlanLayout layout;
  for (std::size_t i = 0; i < scene.corridors.size(); ++i) {
    const scene::Corridor& c = scene.corridors[i];
    const scene::SceneNode* a = scene.find_node(c.from);
    const scene::SceneNode* b = scene.find_node(c.to);
    if (a == nullptr || b == nullptr)
      throw InvalidInputError(fmt::format("corridor '{}': node '{}' does not exist", c.id,
                                          a == nullptr ? c.from : c.to));
    const Eigen::Vector2d d = b->position_m - a->position_m;
    const double length = d.norm();
    if (length < 1e-6)
      throw InvalidInputError(fmt::format(
          "corridor '{}': nodes '{}' and '{}' are at the same place", c.id, c.from, c.to));
    if (c.width_m <= 0)
      throw InvalidInputError(fmt::format("corridor '{}': width_m must be positive", c.id));
    CorridorLayout cl;
    cl.corridor_index = static_cast<int>(i);
    cl.length_m = length;
    cl.rect.origin_m = a->position_m;
    // Axis-aligned corridors keep an exactly axis-aligned frame (no 1e-17 wobble from division).
    if (d.y() == 0.0)
      cl.rect.along = Eigen::Vector2d(d.x() > 0 ? 1.0 : -1.0, 0.0);
    else if (d.x() == 0.0)
      cl.rect.along = Eigen::Vector2d(0.0, d.y() > 0 ? 1.0 : -1.0);
    else
      cl.rect.along = d / length;
    const double half_w = 0.5 * c.width_m;
    cl.rect.s0 = -half_w;
    cl.rect.s1 = length + half_w;
    cl.rect.l0 = -half_w;
    cl.rect.l1 = half_w;
    layout.corridors.push_back(cl);
  }
  for (const CorridorLayout& cl : layout.corridors) {
    const scene::Corridor& c = scene.corridors[cl.corridor_index];
    for (std::size_t r = 0; r < c.rooms.size(); ++r) {
      const scene::RoomRow::Side side = c.rooms[r].side;
      if (side == scene::RoomRow::Side::kLeft || side == scene::RoomRow::Side::kBoth)
        lay_out_room_row(scene, cl, static_cast<int>(r), +1.0, layout);
      if (side == scene::RoomRow::Side::kRight || side == scene::RoomRow::Side::kBoth)
        lay_out_room_row(scene, cl, static_cast<int>(r), -1.0, layout);
    }
  }
  return layout;
}

OrientedRect space_door_rect(const scene::SpaceDoor& door, double wall_thickness_m) {
  OrientedRect r;
  r.origin_m = door.from_m;
  const Eigen::Vector2d d = door.to_m - door.from_m;
  r.along = d.normalized();
  r.s0 = 0.0;
  r.s1 = d.norm();
  r.l0 = -wall_thickness_m;
  r.l1 = wall_thickness_m;
  return r;
}

}  // namespace wifislam::sim::world
