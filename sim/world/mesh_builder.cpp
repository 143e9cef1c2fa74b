#include "sim/world/mesh_builder.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <list>
#include <map>
#include <set>

#include <Eigen/Geometry>

#include "sim/world/poster_layout.hpp"

namespace wifislam::sim::world {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
struct FaceInfo {
  int nesting = -1;
};
using Vb = CGAL::Triangulation_vertex_base_2<Kernel>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel>;
using Fb = CGAL::Constrained_triangulation_face_base_2<Kernel, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

constexpr double kMinTriangleArea = 1e-10;
constexpr double kFrameWidthM = 0.06;
constexpr double kFrameOffsetM = 0.003;
constexpr double kPosterOffsetM = 0.004;
constexpr double kLandmarkOffsetM = 0.006;

/// Nesting level by flood fill across constrained edges (CGAL's polygon triangulation example):
/// odd levels are inside the polygons whose edges were inserted.
void mark_domains(Cdt& cdt) {
  for (auto f : cdt.all_face_handles()) f->info().nesting = -1;
  std::list<Cdt::Edge> border;
  auto flood = [&](Cdt::Face_handle start, int level) {
    if (start->info().nesting != -1) return;
    std::list<Cdt::Face_handle> queue{start};
    while (!queue.empty()) {
      Cdt::Face_handle fh = queue.front();
      queue.pop_front();
      if (fh->info().nesting != -1) continue;
      fh->info().nesting = level;
      for (int i = 0; i < 3; ++i) {
        Cdt::Face_handle n = fh->neighbor(i);
        if (n->info().nesting != -1) continue;
        if (cdt.is_constrained(Cdt::Edge(fh, i)))
          border.emplace_back(fh, i);
        else
          queue.push_back(n);
      }
    }
  };
  flood(cdt.infinite_face(), 0);
  while (!border.empty()) {
    const Cdt::Edge e = border.front();
    border.pop_front();
    Cdt::Face_handle n = e.first->neighbor(e.second);
    if (n->info().nesting == -1) flood(n, e.first->info().nesting + 1);
  }
}

/// Triangles (2-D, counter-clockwise) covering the region bounded by the given segments.
std::vector<std::array<Eigen::Vector2d, 3>> triangulate(
    const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>& segments) {
  Cdt cdt;
  for (const auto& [a, b] : segments) {
    const auto va = cdt.insert(Kernel::Point_2(a.x(), a.y()));
    const auto vb = cdt.insert(Kernel::Point_2(b.x(), b.y()));
    if (va != vb) cdt.insert_constraint(va, vb);
  }
  mark_domains(cdt);
  std::vector<std::array<Eigen::Vector2d, 3>> out;
  for (auto f : cdt.finite_face_handles()) {
    if (f->info().nesting % 2 != 1) continue;
    std::array<Eigen::Vector2d, 3> tri;
    for (int i = 0; i < 3; ++i) {
      const auto& p = f->vertex(i)->point();
      tri[i] = Eigen::Vector2d(p.x(), p.y());
    }
    out.push_back(tri);
  }
  return out;
}

struct Attributes {
  SurfaceKind surface = SurfaceKind::kWall;
  radio_model::WallMaterial material = radio_model::WallMaterial::kPlasterboard;
  int wall_id = -1;
  int variant = 0;
  int decoration = -1;
};

class MeshWriter {
 public:
  explicit MeshWriter(Mesh& mesh) : mesh_(mesh) {}

  /// Adds a planar face: its points, and triangles as index triples into them. Each triangle is
  /// turned so that it is counter-clockwise seen from `normal`'s side.
  void add(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector2d>& uvs,
           const std::vector<std::array<int, 3>>& triangles, const Eigen::Vector3d& normal,
           const Attributes& attr) {
    std::vector<std::uint32_t> index(points.size(), UINT32_MAX);
    for (const auto& t : triangles) {
      const Eigen::Vector3d& p0 = points[t[0]];
      Eigen::Vector3d cross = (points[t[1]] - p0).cross(points[t[2]] - p0);
      if (0.5 * cross.norm() < kMinTriangleArea) continue;
      std::array<int, 3> order = t;
      if (cross.dot(normal) < 0) std::swap(order[1], order[2]);
      Triangle tri;
      for (int k = 0; k < 3; ++k) {
        const int i = order[k];
        if (index[i] == UINT32_MAX) {
          index[i] = static_cast<std::uint32_t>(mesh_.positions_m.size());
          mesh_.positions_m.push_back(points[i].cast<float>());
          mesh_.normals.push_back(normal.cast<float>());
          mesh_.uv_m.push_back(uvs[i].cast<float>());
        }
        tri.v[k] = index[i];
      }
      tri.surface = attr.surface;
      tri.material = attr.material;
      tri.wall_id = attr.wall_id;
      tri.appearance_variant = attr.variant;
      tri.decoration = attr.decoration;
      mesh_.triangles.push_back(tri);
    }
  }

  /// A vertical rectangle over the segment a -> b between heights z0 and z1; `normal2` is the
  /// horizontal direction it faces.
  void add_vertical_rect(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double z0, double z1,
                         const Eigen::Vector2d& normal2, const Attributes& attr,
                         bool uv_from_origin = false) {
    const Eigen::Vector2d dir = (b - a).normalized();
    const double ua = uv_from_origin ? 0.0 : a.dot(dir), ub = ua + (b - a).norm();
    const double va = uv_from_origin ? 0.0 : z0, vb = va + (z1 - z0);
    add({{a.x(), a.y(), z0}, {b.x(), b.y(), z0}, {b.x(), b.y(), z1}, {a.x(), a.y(), z1}},
        {{ua, va}, {ub, va}, {ub, vb}, {ua, vb}}, {{0, 1, 2}, {0, 2, 3}},
        Eigen::Vector3d(normal2.x(), normal2.y(), 0), attr);
  }

  /// A horizontal rectangle (corners in order) at height z facing up or down. Its uv is the plan
  /// position (metres) turned by `uv_rotation_rad`.
  void add_horizontal(const std::vector<Eigen::Vector2d>& corners, double z, bool up,
                      const Attributes& attr, double uv_rotation_rad = 0.0) {
    std::vector<Eigen::Vector3d> pts;
    std::vector<Eigen::Vector2d> uvs;
    std::vector<std::array<int, 3>> tris;
    const Eigen::Rotation2Dd turn(uv_rotation_rad);
    for (const auto& c : corners) {
      pts.emplace_back(c.x(), c.y(), z);
      uvs.push_back(uv_rotation_rad == 0.0 ? c : Eigen::Vector2d(turn * c));
    }
    for (std::size_t i = 1; i + 1 < corners.size(); ++i)
      tris.push_back({0, static_cast<int>(i), static_cast<int>(i + 1)});
    add(pts, uvs, tris, Eigen::Vector3d(0, 0, up ? 1 : -1), attr);
  }

  void add_triangles_2d(const std::vector<std::array<Eigen::Vector2d, 3>>& tris, double z, bool up,
                        const Attributes& attr, double uv_rotation_rad = 0.0) {
    for (const auto& t : tris) add_horizontal({t[0], t[1], t[2]}, z, up, attr, uv_rotation_rad);
  }

 private:
  Mesh& mesh_;
};

/// Key of a plan point, exact to the bit: faces meeting at a corner share the very same doubles.
std::pair<std::uint64_t, std::uint64_t> point_key(const Eigen::Vector2d& p) {
  std::uint64_t x, y;
  std::memcpy(&x, &p.x(), sizeof x);
  std::memcpy(&y, &p.y(), sizeof y);
  return {x, y};
}

/// The face strip between heights z0 and z1 with the extra vertices each vertical edge needs so
/// neighbouring faces meet edge to edge (no T-junctions): the two vertical chains are zipped into
/// triangles.
void add_wall_strip(MeshWriter& writer, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                    const std::set<double>& heights_a, const std::set<double>& heights_b, double z0,
                    double z1, const Attributes& attr) {
  std::vector<double> left, right;
  for (double h : heights_a)
    if (h >= z0 && h <= z1) left.push_back(h);
  for (double h : heights_b)
    if (h >= z0 && h <= z1) right.push_back(h);
  const Eigen::Vector2d dir = (b - a).normalized();
  const Eigen::Vector2d normal(-dir.y(), dir.x());
  const double ua = a.dot(dir), ub = b.dot(dir);
  std::vector<Eigen::Vector3d> pts;
  std::vector<Eigen::Vector2d> uvs;
  for (double h : left) pts.emplace_back(a.x(), a.y(), h), uvs.emplace_back(ua, h);
  for (double h : right) pts.emplace_back(b.x(), b.y(), h), uvs.emplace_back(ub, h);
  const int nl = static_cast<int>(left.size()), nr = static_cast<int>(right.size());
  std::vector<std::array<int, 3>> tris;
  int i = 0, j = 0;
  while (i < nl - 1 || j < nr - 1) {
    const bool step_left = j == nr - 1 || (i < nl - 1 && left[i + 1] <= right[j + 1]);
    if (step_left) {
      tris.push_back({i, nl + j, i + 1});
      ++i;
    } else {
      tris.push_back({i, nl + j, nl + j + 1});
      ++j;
    }
  }
  writer.add(pts, uvs, tris, Eigen::Vector3d(normal.x(), normal.y(), 0), attr);
}

using CornerHeights = std::map<std::pair<std::uint64_t, std::uint64_t>, std::set<double>>;

/// Heights at which each wall corner's vertical edge is cut: floor, top, and door heights of the
/// door leaves that end there.
CornerHeights corner_heights(const FloorPlan& plan) {
  CornerHeights heights;
  for (const WallFace2& f : plan.wall_faces) {
    for (const auto* p : {&f.a_m, &f.b_m}) {
      auto& hs = heights[point_key(*p)];
      hs.insert(0.0);
      hs.insert(plan.wall_height_m);
      if (f.door_index >= 0) hs.insert(plan.doors[f.door_index].height_m);
    }
  }
  return heights;
}

/// One wall face, or for a closed door's face its leaf below the door height and the lintel
/// above it.
void add_wall_face(MeshWriter& writer, const FloorPlan& plan, const WallFace2& f,
                   const CornerHeights& corners) {
  const double height = plan.wall_height_m;
  Attributes attr;
  attr.surface = SurfaceKind::kWall;
  attr.material = f.material;
  attr.wall_id = f.wall_id;
  attr.variant =
      f.appearance_segment >= 0 ? plan.appearance_segments[f.appearance_segment].variant : 0;
  // Every face's corners are in `corners` (corner_heights visits them all).
  const auto& ha = corners.at(point_key(f.a_m));
  const auto& hb = corners.at(point_key(f.b_m));
  if (f.door_index < 0) {
    add_wall_strip(writer, f.a_m, f.b_m, ha, hb, 0.0, height, attr);
    return;
  }
  const Door& door = plan.doors[f.door_index];
  Attributes leaf = attr;
  leaf.surface = SurfaceKind::kDoor;
  leaf.material = radio_model::WallMaterial::kWoodDoor;
  add_wall_strip(writer, f.a_m, f.b_m, ha, hb, 0.0, door.height_m, leaf);
  Attributes lintel = attr;
  lintel.material = plan.rooms[door.room_index].material;
  add_wall_strip(writer, f.a_m, f.b_m, ha, hb, door.height_m, height, lintel);
}

/// Caps on top of and underneath the wall solids.
void add_wall_caps(MeshWriter& writer, const FloorPlan& plan) {
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> segments;
  for (const WallFace2& f : plan.wall_faces) segments.emplace_back(f.a_m, f.b_m);
  const auto tris = triangulate(segments);
  Attributes cap;
  cap.surface = SurfaceKind::kWallTop;
  writer.add_triangles_2d(tris, plan.wall_height_m, true, cap);
  writer.add_triangles_2d(tris, 0.0, false, cap);
}

/// Every edge of every free-space region, outer rings and holes.
std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> free_space_edges(const FloorPlan& plan) {
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> segments;
  auto add_ring = [&](const Polygon2& r) {
    for (std::size_t i = 0; i < r.size(); ++i) segments.emplace_back(r[i], r[(i + 1) % r.size()]);
  };
  for (const auto& region : plan.free_space) {
    add_ring(region.outer);
    for (const auto& h : region.holes) add_ring(h);
  }
  return segments;
}

/// Floor and ceiling over all free space.
void add_floor_and_ceiling(MeshWriter& writer, const FloorPlan& plan) {
  const auto tris = triangulate(free_space_edges(plan));
  Attributes floor;
  floor.surface = SurfaceKind::kFloor;
  floor.material = radio_model::WallMaterial::kConcrete;
  // Floor and ceiling textures tile (12 m and 9.6 m, see procedural_textures.cpp). Laid at an
  // angle to the plan axes, a shift along a corridor (x or y) maps the tiling onto itself only
  // after hundreds of metres, so no two places of a corridor share a floor or ceiling pattern.
  constexpr double kFloorUvRotationRad = 23.0 * M_PI / 180.0;
  constexpr double kCeilingUvRotationRad = 37.0 * M_PI / 180.0;
  writer.add_triangles_2d(tris, 0.0, true, floor, kFloorUvRotationRad);
  Attributes ceiling;
  ceiling.surface = SurfaceKind::kCeiling;
  writer.add_triangles_2d(tris, plan.wall_height_m, false, ceiling, kCeilingUvRotationRad);
}

/// A vertical rectangle between a and b facing `facing`: the points are swapped when needed so
/// that a -> b has `facing` on its left.
void add_facing_rect(MeshWriter& writer, Eigen::Vector2d a, Eigen::Vector2d b, double z0, double z1,
                     const Eigen::Vector2d& facing, const Attributes& attr) {
  if (Eigen::Vector2d(-(b - a).y(), (b - a).x()).dot(facing) < 0) std::swap(a, b);
  writer.add_vertical_rect(a, b, z0, z1, facing, attr);
}

/// The frame around a door on both faces of its wall: two jambs, and a head when the wall is
/// taller than the door.
void add_door_frame(MeshWriter& writer, const Door& door, double wall_height_m) {
  const Eigen::Vector2d u = door.along_wall, n(-u.y(), u.x());
  const double hw = 0.5 * door.width_m, ht = 0.5 * door.wall_thickness_m, h = door.height_m;
  const double top = std::min(h + kFrameWidthM, wall_height_m);
  Attributes frame;
  frame.surface = SurfaceKind::kDoorFrame;
  frame.material = radio_model::WallMaterial::kWoodDoor;
  for (double side : {1.0, -1.0}) {
    const Eigen::Vector2d facing = side * n;
    const Eigen::Vector2d base = door.center_m + (ht + kFrameOffsetM) * facing;
    auto strip = [&](double s0, double s1, double z0, double z1) {
      const Eigen::Vector2d a = base + s0 * u, b = base + s1 * u;
      add_facing_rect(writer, a, b, z0, z1, facing, frame);
    };
    strip(-hw - kFrameWidthM, -hw, 0.0, top);
    strip(hw, hw + kFrameWidthM, 0.0, top);
    if (top > h) strip(-hw, hw, h, top);
  }
}

/// The wall above an open door (door `d`): both faces and the underside, as a wall of its own.
void add_open_door_lintel(MeshWriter& writer, const FloorPlan& plan, std::size_t d) {
  const Door& door = plan.doors[d];
  const Eigen::Vector2d u = door.along_wall, n(-u.y(), u.x());
  const double hw = 0.5 * door.width_m, ht = 0.5 * door.wall_thickness_m, h = door.height_m;
  Attributes lintel;
  lintel.surface = SurfaceKind::kDoorFrame;
  lintel.material = plan.rooms[door.room_index].material;
  lintel.wall_id = plan.wall_count + static_cast<int>(d);
  for (double side : {1.0, -1.0}) {
    const Eigen::Vector2d facing = side * n;
    const Eigen::Vector2d a = door.center_m + ht * facing - hw * u,
                          b = door.center_m + ht * facing + hw * u;
    add_facing_rect(writer, a, b, h, plan.wall_height_m, facing, lintel);
  }
  writer.add_horizontal({door.center_m - hw * u - ht * n, door.center_m + hw * u - ht * n,
                         door.center_m + hw * u + ht * n, door.center_m - hw * u + ht * n},
                        h, false, lintel);
}

/// Door frames on both faces of every door; lintels over open doors.
void add_doors(MeshWriter& writer, const FloorPlan& plan) {
  for (std::size_t d = 0; d < plan.doors.size(); ++d) {
    add_door_frame(writer, plan.doors[d], plan.wall_height_m);
    if (plan.doors[d].open) add_open_door_lintel(writer, plan, d);
  }
}

void add_ceiling_lights(MeshWriter& writer, const FloorPlan& plan) {
  for (const CeilingLight& light : plan.lights) {
    const Eigen::Vector2d c = light.center_m.head<2>(), s = 0.5 * light.size_m;
    Attributes attr;
    attr.surface = SurfaceKind::kLight;
    writer.add_horizontal({c + Eigen::Vector2d(-s.x(), -s.y()), c + Eigen::Vector2d(s.x(), -s.y()),
                           c + Eigen::Vector2d(s.x(), s.y()), c + Eigen::Vector2d(-s.x(), s.y())},
                          light.center_m.z(), false, attr);
  }
}

/// Posters and landmarks, just off the wall face they hang on.
void add_posters(MeshWriter& writer, const scene::Scene& scene, const FloorPlan& plan) {
  for (const PosterPlacement& p : place_posters(scene, plan)) {
    Attributes attr;
    attr.surface = SurfaceKind::kPoster;
    attr.material = plan.wall_faces[p.face_index].material;
    attr.variant = p.appearance_variant;
    attr.decoration = p.decoration;
    const Eigen::Vector2d base =
        p.center_m + (p.landmark ? kLandmarkOffsetM : kPosterOffsetM) * p.normal;
    writer.add_vertical_rect(base - 0.5 * p.width_m * p.along, base + 0.5 * p.width_m * p.along,
                             p.center_height_m - 0.5 * p.height_m,
                             p.center_height_m + 0.5 * p.height_m, p.normal, attr, true);
  }
}

}  // namespace

Mesh build_mesh(const scene::Scene& scene, const FloorPlan& plan) {
  Mesh mesh;
  MeshWriter writer(mesh);
  const CornerHeights corners = corner_heights(plan);
  for (const WallFace2& f : plan.wall_faces) add_wall_face(writer, plan, f, corners);
  add_wall_caps(writer, plan);
  add_floor_and_ceiling(writer, plan);
  add_doors(writer, plan);
  add_ceiling_lights(writer, plan);
  add_posters(writer, scene, plan);
  return mesh;
}

}  // namespace wifislam::sim::world
