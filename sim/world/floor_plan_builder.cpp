#include "sim/world/floor_plan_builder.hpp"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/minkowski_sum_2.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include <fmt/format.h>

#include "core/error.hpp"
#include "sim/world/ceiling_lights.hpp"
#include "sim/world/plan_layout.hpp"
#include "sim/world/plan_queries.hpp"
#include "sim/world/wall_faces.hpp"

namespace wifislam::sim::world {

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = Kernel::FT;
using Point = Kernel::Point_2;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWH = CGAL::Polygon_with_holes_2<Kernel>;
using PolygonSet = CGAL::Polygon_set_2<Kernel>;

/// The rectangle's corners computed in exact arithmetic from the (double) frame, so points on one
/// frame line stay exactly collinear even for corridors that are not axis-aligned.
Polygon exact_rect(const OrientedRect& r) {
  const FT ox(r.origin_m.x()), oy(r.origin_m.y()), ax(r.along.x()), ay(r.along.y());
  auto pt = [&](double s, double l) {
    const FT fs(s), fl(l);
    return Point(ox + fs * ax - fl * ay, oy + fs * ay + fl * ax);
  };
  Polygon p;
  p.push_back(pt(r.s0, r.l0));
  p.push_back(pt(r.s1, r.l0));
  p.push_back(pt(r.s1, r.l1));
  p.push_back(pt(r.s0, r.l1));
  return p;
}

Polygon exact_polygon(const Polygon2& ring) {
  Polygon p;
  for (const auto& v : ring) p.push_back(Point(v.x(), v.y()));
  return p;
}

/// Dilation kernel for open areas: a square is exact for axis-aligned walls; an octagon (in-radius
/// = thickness) keeps 45-degree walls at the right thickness too and others within 8 %.
Polygon dilation_kernel(double thickness_m, bool axis_aligned) {
  Polygon k;
  if (axis_aligned) {
    const FT t(thickness_m);
    k.push_back(Point(-t, -t));
    k.push_back(Point(t, -t));
    k.push_back(Point(t, t));
    k.push_back(Point(-t, t));
    return k;
  }
  const double circum = thickness_m / std::cos(M_PI / 8);
  for (int i = 0; i < 8; ++i) {
    const double a = M_PI / 8 + i * M_PI / 4;
    k.push_back(Point(circum * std::cos(a), circum * std::sin(a)));
  }
  return k;
}

bool is_axis_aligned(const Polygon2& ring) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Eigen::Vector2d& a = ring[i];
    const Eigen::Vector2d& b = ring[(i + 1) % ring.size()];
    if (a.x() != b.x() && a.y() != b.y()) return false;
  }
  return true;
}

/// Exact ring -> double ring without collinear vertices, starting at its smallest vertex so the
/// output does not depend on where CGAL happened to start the boundary.
Polygon2 to_double_ring(const Polygon& ring, bool counter_clockwise) {
  std::vector<Point> pts(ring.vertices_begin(), ring.vertices_end());
  const std::size_t n = pts.size();
  Polygon2 out;
  for (std::size_t i = 0; i < n; ++i) {
    if (CGAL::collinear(pts[(i + n - 1) % n], pts[i], pts[(i + 1) % n])) continue;
    out.emplace_back(CGAL::to_double(pts[i].x()), CGAL::to_double(pts[i].y()));
  }
  // Drop vertices that rounding made coincide.
  Polygon2 clean;
  for (const auto& v : out)
    if (clean.empty() || (v - clean.back()).norm() > 1e-9) clean.push_back(v);
  while (clean.size() > 1 && (clean.front() - clean.back()).norm() <= 1e-9) clean.pop_back();
  if ((ring_signed_area_m2(clean) > 0) != counter_clockwise)
    std::reverse(clean.begin(), clean.end());
  auto smallest = std::min_element(clean.begin(), clean.end(), [](const auto& a, const auto& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  std::rotate(clean.begin(), smallest, clean.end());
  return clean;
}

std::vector<PolygonWithHoles2> to_double_regions(const PolygonSet& set) {
  std::vector<PolygonWH> exact;
  set.polygons_with_holes(std::back_inserter(exact));
  std::vector<PolygonWithHoles2> out;
  for (const auto& pwh : exact) {
    PolygonWithHoles2 r;
    r.outer = to_double_ring(pwh.outer_boundary(), true);
    if (r.outer.size() < 3) continue;
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) {
      Polygon2 hole = to_double_ring(*h, false);
      if (hole.size() >= 3) r.holes.push_back(std::move(hole));
    }
    auto first_vertex_less = [](const Polygon2& a, const Polygon2& b) {
      return a[0].x() < b[0].x() || (a[0].x() == b[0].x() && a[0].y() < b[0].y());
    };
    std::sort(r.holes.begin(), r.holes.end(), first_vertex_less);
    out.push_back(std::move(r));
  }
  std::sort(out.begin(), out.end(), [](const PolygonWithHoles2& a, const PolygonWithHoles2& b) {
    return a.outer[0].x() < b.outer[0].x() ||
           (a.outer[0].x() == b.outer[0].x() && a.outer[0].y() < b.outer[0].y());
  });
  return out;
}

PolygonSet join_all(const std::vector<Polygon>& pieces) {
  PolygonSet set;
  if (!pieces.empty()) set.join(pieces.begin(), pieces.end());
  return set;
}

struct Box {
  double x0, y0, x1, y1;
  bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};
Box box_of(const Polygon& p) {
  const CGAL::Bbox_2 b = p.bbox();
  return {b.xmin(), b.ymin(), b.xmax(), b.ymax()};
}

void check_building(const scene::Scene& scene) {
  if (!(scene.building.wall_thickness_m > 0))
    throw InvalidInputError("building.wall_thickness_m must be positive");
  if (!(scene.building.wall_height_m > 0))
    throw InvalidInputError("building.wall_height_m must be positive");
}

/// The exact polygons the plan is joined from.
struct ExactPieces {
  std::vector<Polygon> corridors, open_areas, pillars;
  /// Spaces of kind room (free, not walkable) and the doorways of open space doors, split by
  /// whether both sides are walkable (then the doorway is walkable too).
  std::vector<Polygon> space_rooms, room_doorways, walkable_doorways;
  /// Every space grown by the wall thickness: the walls are what of it is not free space.
  std::vector<Polygon> dilated;
};

/// Open area `i`: its outline (counter-clockwise), its dilation and its pillars. Rejects an
/// outline that is not a simple polygon with an area.
void add_open_area(const scene::Scene& scene, std::size_t i, double wall_thickness_m,
                   ExactPieces& pieces) {
  const scene::OpenArea& area = scene.open_areas[i];
  Polygon p = exact_polygon(area.polygon_m);
  if (area.polygon_m.size() < 3 || !p.is_simple() || p.area() == 0) {
    scene.reject(fmt::format("open_areas[{}].polygon_m", i),
                 fmt::format("open area '{}': the outline crosses or touches itself, or encloses "
                             "no area; list the corners once around the area, in order",
                             area.id));
  }
  if (p.is_clockwise_oriented()) p.reverse_orientation();
  const PolygonWH grown =
      CGAL::minkowski_sum_2(p, dilation_kernel(wall_thickness_m, is_axis_aligned(area.polygon_m)));
  pieces.dilated.push_back(grown.outer_boundary());
  pieces.open_areas.push_back(p);
  for (const scene::OpenArea::Pillar& pillar : area.pillars) {
    OrientedRect r;
    r.origin_m = pillar.center_m;
    r.s0 = r.l0 = -0.5 * pillar.size_m;
    r.s1 = r.l1 = 0.5 * pillar.size_m;
    pieces.pillars.push_back(exact_rect(r));
  }
}

/// A simple polygon with an area, counter-clockwise, else rejected at `key`.
Polygon checked_polygon(const scene::Scene& scene, const Polygon2& ring, const std::string& key,
                        const std::string& what) {
  Polygon p = exact_polygon(ring);
  if (ring.size() < 3 || !p.is_simple() || p.area() == 0) {
    scene.reject(key, fmt::format("{}: the outline crosses or touches itself, or encloses no "
                                  "area; list the corners once around it, in order",
                                  what));
  }
  if (p.is_clockwise_oriented()) p.reverse_orientation();
  return p;
}

/// Whether p lies in a walkable space (corridor or area kind).
bool in_walkable_space(const scene::Scene& scene, const Eigen::Vector2d& p) {
  for (const scene::Space& s : scene.spaces)
    if (s.kind != scene::SpaceKind::kRoom && ring_contains(s.polygon_m, p)) return true;
  return false;
}

/// Spaces (walls grown around each like around an open area), obstacles (like pillars) and the
/// doorways of open doors (one wall thickness to either side of the door's centre line, so they
/// overlap the spaces on both sides).
void add_spaces(const scene::Scene& scene, double wall_thickness_m, ExactPieces& pieces) {
  for (std::size_t i = 0; i < scene.spaces.size(); ++i) {
    const scene::Space& space = scene.spaces[i];
    const Polygon p =
        checked_polygon(scene, space.polygon_m, fmt::format("spaces[{}].polygon_m", i),
                        fmt::format("space '{}'", space.id));
    const PolygonWH grown = CGAL::minkowski_sum_2(
        p, dilation_kernel(wall_thickness_m, is_axis_aligned(space.polygon_m)));
    pieces.dilated.push_back(grown.outer_boundary());
    (space.kind == scene::SpaceKind::kRoom ? pieces.space_rooms : pieces.open_areas).push_back(p);
  }
  for (std::size_t i = 0; i < scene.obstacles.size(); ++i)
    pieces.pillars.push_back(checked_polygon(scene, scene.obstacles[i].polygon_m,
                                             fmt::format("obstacles[{}].polygon_m", i),
                                             fmt::format("obstacle {}", i)));
  for (const scene::SpaceDoor& door : scene.doors) {
    if (!door.open) continue;
    const OrientedRect r = space_door_rect(door, wall_thickness_m);
    const Eigen::Vector2d n = r.left() * (0.5 * wall_thickness_m + 0.05);
    const Eigen::Vector2d c = r.center();
    const bool walkable = in_walkable_space(scene, c + n) && in_walkable_space(scene, c - n);
    (walkable ? pieces.walkable_doorways : pieces.room_doorways).push_back(exact_rect(r));
  }
}

/// Corridors, then open areas, then spaces, in scene order.
ExactPieces exact_pieces(const scene::Scene& scene, const PlanLayout& layout,
                         double wall_thickness_m) {
  ExactPieces pieces;
  for (const CorridorLayout& c : layout.corridors) {
    pieces.corridors.push_back(exact_rect(c.rect));
    pieces.dilated.push_back(exact_rect(c.rect.grown(wall_thickness_m)));
  }
  for (std::size_t i = 0; i < scene.open_areas.size(); ++i)
    add_open_area(scene, i, wall_thickness_m, pieces);
  add_spaces(scene, wall_thickness_m, pieces);
  return pieces;
}

/// Whether `footprint` overlaps any occupied polygon; the boxes skip the far ones cheaply.
bool overlaps_occupied(const Polygon& footprint, const std::vector<Polygon>& occupied,
                       const std::vector<Box>& occupied_boxes) {
  const Box fb = box_of(footprint);
  std::vector<Polygon> near;
  for (std::size_t k = 0; k < occupied.size(); ++k)
    if (occupied_boxes[k].overlaps(fb)) near.push_back(occupied[k]);
  if (near.empty()) return false;
  PolygonSet clash = join_all(near);
  clash.intersection(footprint);
  return !clash.is_empty();
}

/// The room candidates that are kept, as indices into layout.rooms, with their exact rooms and
/// the doorways of their open doors.
struct KeptRooms {
  std::vector<int> candidates;
  std::vector<Polygon> rooms, open_doors;
};

/// Keeps a room only when it and its walls overlap no free space placed before it; adds the
/// kept rooms' footprints to pieces.dilated.
KeptRooms keep_rooms(const PlanLayout& layout, double wall_thickness_m, ExactPieces& pieces) {
  std::vector<Polygon> occupied = pieces.corridors;
  occupied.insert(occupied.end(), pieces.open_areas.begin(), pieces.open_areas.end());
  std::vector<Box> occupied_boxes;
  for (const auto& p : occupied) occupied_boxes.push_back(box_of(p));
  KeptRooms kept;
  for (std::size_t i = 0; i < layout.rooms.size(); ++i) {
    const RoomCandidate& cand = layout.rooms[i];
    const Polygon room = exact_rect(cand.room);
    const Polygon footprint = exact_rect(cand.room.grown(wall_thickness_m));
    // The clash test uses a footprint a hair smaller: the grown rectangle's edge is computed in
    // double and may overlap its own corridor by a rounding error.
    const Polygon clash_footprint = exact_rect(cand.room.grown(wall_thickness_m - 1e-7));
    if (overlaps_occupied(clash_footprint, occupied, occupied_boxes)) continue;
    kept.candidates.push_back(static_cast<int>(i));
    kept.rooms.push_back(room);
    occupied.push_back(room);
    occupied_boxes.push_back(box_of(room));
    pieces.dilated.push_back(footprint);
    if (cand.door_open) kept.open_doors.push_back(exact_rect(cand.door));
  }
  return kept;
}

/// Joins the pieces into free space (corridors, open areas, kept rooms, open doorways), walkable
/// space (corridors and open areas) and walls, and stores them in doubles in the plan.
void set_plan_regions(const ExactPieces& pieces, const KeptRooms& kept, FloorPlan& plan) {
  std::vector<Polygon> walkable_parts = pieces.corridors;
  for (const auto* part : {&pieces.open_areas, &pieces.walkable_doorways})
    walkable_parts.insert(walkable_parts.end(), part->begin(), part->end());
  PolygonSet walkable = join_all(walkable_parts);
  std::vector<Polygon> free_parts = walkable_parts;
  for (const auto* part :
       {&kept.rooms, &kept.open_doors, &pieces.space_rooms, &pieces.room_doorways})
    free_parts.insert(free_parts.end(), part->begin(), part->end());
  PolygonSet free_space = join_all(free_parts);
  if (!pieces.pillars.empty()) {
    const PolygonSet pillar_set = join_all(pieces.pillars);
    walkable.difference(pillar_set);
    free_space.difference(pillar_set);
  }
  PolygonSet walls = join_all(pieces.dilated);
  walls.difference(free_space);
  plan.free_space = to_double_regions(free_space);
  plan.walkable = to_double_regions(walkable);
  plan.walls = to_double_regions(walls);
}

/// The robot's space must be one piece.
void check_walkable_connected(const FloorPlan& plan) {
  if (plan.walkable.empty())
    throw InvalidInputError("the scene has no corridors, open areas or walkable spaces");
  if (plan.walkable.size() > 1) {
    const Eigen::Vector2d p = plan.walkable[1].outer[0];
    throw InvalidInputError(
        fmt::format("the corridors, open areas and walkable spaces form {} separate pieces (one "
                    "starts near ({:.2f}, {:.2f})); "
                    "the robot's space must be connected",
                    plan.walkable.size(), p.x(), p.y()));
  }
}

/// A room and its door for each kept candidate, in candidate order.
void add_rooms_and_doors(const scene::Scene& scene, const PlanLayout& layout,
                         const std::vector<int>& kept_candidates, FloorPlan& plan) {
  const double door_height_m = std::min(2.1, scene.building.wall_height_m - 0.2);
  for (int index : kept_candidates) {
    const RoomCandidate& cand = layout.rooms[index];
    Room room;
    room.polygon_m = cand.room.corners();
    room.corridor_id = scene.corridors[cand.corridor_index].id;
    room.material = cand.material;
    room.door_index = static_cast<int>(plan.doors.size());
    Door door;
    door.center_m = cand.door.center();
    door.along_wall = cand.door.along;
    door.width_m = cand.door.s1 - cand.door.s0;
    door.height_m = door_height_m;
    door.wall_thickness_m = plan.wall_thickness_m;
    door.open = cand.door_open;
    door.room_index = static_cast<int>(plan.rooms.size());
    plan.rooms.push_back(std::move(room));
    plan.doors.push_back(door);
  }
}

/// The nearest room space within one wall thickness of p (a door's centre), or -1.
int room_space_near(const scene::Scene& scene, const Eigen::Vector2d& p, double wall_thickness_m) {
  int best = -1, room = 0;
  double best_d = wall_thickness_m + 1e-6;
  for (const scene::Space& s : scene.spaces) {
    if (s.kind != scene::SpaceKind::kRoom) continue;
    double d = ring_contains(s.polygon_m, p) ? 0.0 : 1e300;
    for (std::size_t k = 0, n = s.polygon_m.size(); k < n; ++k)
      d = std::min(d, segment_distance_m(p, s.polygon_m[k], s.polygon_m[(k + 1) % n]));
    if (d < best_d) best_d = d, best = room;
    ++room;
  }
  return best;
}

/// Rooms of the spaces of kind room, then the space doors, after the corridors' rooms: a door
/// belongs to the room space it opens into (if any), a room to its first door.
void add_space_rooms_and_doors(const scene::Scene& scene, FloorPlan& plan) {
  const int first_room = static_cast<int>(plan.rooms.size());
  for (const scene::Space& s : scene.spaces) {
    if (s.kind != scene::SpaceKind::kRoom) continue;
    Room room;
    room.polygon_m = s.polygon_m;
    if (ring_signed_area_m2(room.polygon_m) < 0)
      std::reverse(room.polygon_m.begin(), room.polygon_m.end());
    room.material = s.material;
    plan.rooms.push_back(std::move(room));
  }
  const double door_height_m = std::min(2.1, scene.building.wall_height_m - 0.2);
  for (const scene::SpaceDoor& d : scene.doors) {
    const OrientedRect r = space_door_rect(d, plan.wall_thickness_m);
    Door door;
    door.center_m = r.center();
    door.along_wall = r.along;
    door.width_m = r.s1 - r.s0;
    door.height_m = door_height_m;
    door.wall_thickness_m = plan.wall_thickness_m;
    door.open = d.open;
    const int room = room_space_near(scene, door.center_m, plan.wall_thickness_m);
    if (room >= 0) {
      door.room_index = first_room + room;
      Room& owner = plan.rooms[door.room_index];
      if (owner.door_index < 0) owner.door_index = static_cast<int>(plan.doors.size());
    }
    plan.doors.push_back(door);
  }
}

/// Bounding box of the walls and the free space.
void set_bounds(FloorPlan& plan) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = Eigen::Vector2d::Constant(-1e300);
  for (const auto* regions : {&plan.walls, &plan.free_space})
    for (const auto& r : *regions)
      for (const auto& v : r.outer) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  plan.bounds_min_m = lo;
  plan.bounds_max_m = hi;
}

}  // namespace

FloorPlan build_floor_plan(const scene::Scene& scene, bool robot_space) {
  check_building(scene);
  const double t = scene.building.wall_thickness_m;
  const PlanLayout layout = lay_out_scene(scene);
  ExactPieces pieces = exact_pieces(scene, layout, t);
  const KeptRooms kept = keep_rooms(layout, t, pieces);

  FloorPlan plan;
  plan.wall_height_m = scene.building.wall_height_m;
  plan.wall_thickness_m = t;
  set_plan_regions(pieces, kept, plan);
  if (robot_space) check_walkable_connected(plan);
  add_rooms_and_doors(scene, layout, kept.candidates, plan);
  add_space_rooms_and_doors(scene, plan);
  build_wall_faces(scene, layout, plan);
  plan.lights = place_ceiling_lights(scene, layout, plan);
  set_bounds(plan);
  return plan;
}

}  // namespace wifislam::sim::world
