#include "tests/sim/world/world_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>

#include <Eigen/Geometry>

#include "sim/world/plan_queries.hpp"

namespace wifislam::test {

sim::scene::Scene square_loop_scene(double side_m, double width_m, bool doors_open) {
  sim::scene::Scene s;
  s.name = "square_loop";
  s.seed = 7;
  s.nodes = {{"A", {0, 0}}, {"B", {side_m, 0}}, {"C", {side_m, side_m}}, {"D", {0, side_m}}};
  const std::vector<std::pair<std::string, std::string>> legs = {
      {"A", "B"}, {"B", "C"}, {"C", "D"}, {"D", "A"}};
  for (const auto& [from, to] : legs) {
    sim::scene::Corridor c;
    c.id = from + to;
    c.from = from;
    c.to = to;
    c.width_m = width_m;
    sim::scene::RoomRow outside;
    outside.side = sim::scene::RoomRow::Side::kRight;  // the loop runs counter-clockwise
    outside.from_m = 1.0;
    outside.to_m = side_m - 1.0;
    outside.room_length_m = 3.0;
    outside.depth_m = 3.0;
    outside.door_offset_m = 1.0;
    outside.doors_open = doors_open;
    c.rooms.push_back(outside);
    s.corridors.push_back(c);
  }
  // Inside rooms along the south corridor; the first and last run into the side corridors and
  // must be dropped.
  sim::scene::RoomRow inside;
  inside.side = sim::scene::RoomRow::Side::kLeft;
  inside.from_m = 0.0;
  inside.to_m = side_m;
  inside.room_length_m = 3.5;
  inside.depth_m = 3.0;
  inside.door_offset_m = 1.2;
  inside.doors_open = !doors_open;
  inside.material = radio_model::WallMaterial::kConcrete;
  s.corridors[0].rooms.push_back(inside);
  s.route.nodes = {"A", "B", "C", "D", "A"};
  s.appearance.aliasing = 0.5;
  s.appearance.posters_per_10m = 2.0;
  return s;
}

namespace {

Eigen::Vector2d left_of(const sim::world::WallFace2& f) {
  const Eigen::Vector2d d = (f.b_m - f.a_m).normalized();
  return {-d.y(), d.x()};
}

}  // namespace

namespace {

/// Every free-space piece holds the robot's space or is a room behind a closed door; returns the
/// walkable piece's index.
void expect_free_space_reachable(const sim::world::World& world, int& walkable_piece) {
  const sim::world::FloorPlan& plan = world.plan;
  // Every free-space piece holds the robot's space or is a room behind a closed door.
  ASSERT_FALSE(world.route.points_m.empty());
  walkable_piece = sim::world::regions_find(plan.free_space, world.route.points_m.front());
  ASSERT_GE(walkable_piece, 0);
  for (std::size_t k = 0; k < plan.free_space.size(); ++k) {
    bool closed_room = false;
    for (const sim::world::Room& r : plan.rooms) {
      Eigen::Vector2d c = Eigen::Vector2d::Zero();
      for (const auto& v : r.polygon_m) c += v;
      c /= static_cast<double>(r.polygon_m.size());
      if (sim::world::region_contains(plan.free_space[k], c) && !plan.doors[r.door_index].open)
        closed_room = true;
    }
    EXPECT_TRUE(static_cast<int>(k) == walkable_piece || closed_room)
        << "a free-space piece near (" << plan.free_space[k].outer[0].transpose()
        << ") is unreachable";
  }
}

void expect_rooms_apart(const sim::world::FloorPlan& plan) {
  // Rooms: not in walkable space, not overlapping each other, each with its door.
  for (std::size_t i = 0; i < plan.rooms.size(); ++i) {
    const sim::world::Room& r = plan.rooms[i];
    Eigen::Vector2d lo = r.polygon_m[0], hi = r.polygon_m[0];
    for (const auto& v : r.polygon_m) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    for (double fx = 0.05; fx < 1; fx += 0.1) {
      for (double fy = 0.05; fy < 1; fy += 0.1) {
        const Eigen::Vector2d p = lo + (hi - lo).cwiseProduct(Eigen::Vector2d(fx, fy));
        if (!sim::world::ring_contains(r.polygon_m, p)) continue;
        EXPECT_FALSE(sim::world::regions_contain(plan.walkable, p))
            << "room " << i << " overlaps a corridor";
        for (std::size_t j = 0; j < plan.rooms.size(); ++j)
          if (j != i) {
            EXPECT_FALSE(sim::world::ring_contains(plan.rooms[j].polygon_m, p)) << i << " vs " << j;
          }
      }
    }
    ASSERT_GE(r.door_index, 0);
    EXPECT_EQ(plan.doors[r.door_index].room_index, static_cast<int>(i));
  }
}

void expect_wall_faces(const sim::scene::Scene& scene, const sim::world::FloorPlan& plan) {
  // Wall faces: free space (or the outside) on the left, wall on the right.
  for (const sim::world::WallFace2& f : plan.wall_faces) {
    const Eigen::Vector2d mid = 0.5 * (f.a_m + f.b_m), n = left_of(f);
    EXPECT_GT((f.b_m - f.a_m).norm(), 1e-6);
    EXPECT_TRUE(sim::world::regions_contain(plan.walls, mid - 1e-3 * n))
        << "wall not right of a face";
    EXPECT_FALSE(sim::world::regions_contain(plan.walls, mid + 1e-3 * n)) << "wall left of a face";
    EXPECT_EQ(sim::world::regions_contain(plan.free_space, mid + 1e-3 * n), !f.exterior);
    EXPECT_GE(f.wall_id, 0);
    EXPECT_LT(f.wall_id, plan.wall_count);
    if (!f.exterior) {
      ASSERT_GE(f.appearance_segment, 0);
      ASSERT_LT(f.appearance_segment, static_cast<int>(plan.appearance_segments.size()));
      EXPECT_LE((f.b_m - f.a_m).norm(), scene.appearance.segment_length_m + 1e-9);
    }
  }
}

void expect_doors(const sim::world::FloorPlan& plan, int walkable_piece) {
  // Doors: an open door's opening is free space joined to the corridor; a closed door's opening
  // is wall, and crossing it meets kWoodDoor faces only.
  for (const sim::world::Door& d : plan.doors) {
    const Eigen::Vector2d n(-d.along_wall.y(), d.along_wall.x());
    for (double fs : {-0.4, 0.0, 0.4}) {
      for (double fl : {-0.4, 0.0, 0.4}) {
        const Eigen::Vector2d p =
            d.center_m + fs * d.width_m * d.along_wall + fl * d.wall_thickness_m * n;
        if (d.open) {
          EXPECT_TRUE(sim::world::regions_contain(plan.free_space, p)) << "open door not open";
          EXPECT_FALSE(sim::world::regions_contain(plan.walls, p)) << "open door blocked";
          EXPECT_EQ(sim::world::regions_find(plan.free_space, p), walkable_piece);
        } else {
          EXPECT_FALSE(sim::world::regions_contain(plan.free_space, p)) << "closed door is open";
          EXPECT_TRUE(sim::world::regions_contain(plan.walls, p)) << "closed door has no leaf";
        }
      }
    }
    if (!d.open) {
      for (double side : {-1.0, 1.0}) {
        int face = -1;
        sim::world::nearest_wall_distance_m(
            plan, d.center_m + side * (0.5 * d.wall_thickness_m + 0.01) * n, &face);
        ASSERT_GE(face, 0);
        EXPECT_EQ(plan.wall_faces[face].material, radio_model::WallMaterial::kWoodDoor);
      }
    }
  }
}

void expect_route(const sim::scene::Scene& scene, const sim::world::World& world) {
  const sim::world::FloorPlan& plan = world.plan;
  // The route: dense, inside walkable space, clear of the walls.
  const sim::world::RoutePath& route = world.route;
  ASSERT_GE(route.points_m.size(), 2u);
  ASSERT_EQ(route.arc_length_m.size(), route.points_m.size());
  ASSERT_EQ(route.heading_rad.size(), route.points_m.size());
  for (std::size_t k = 0; k < route.points_m.size(); ++k) {
    const Eigen::Vector2d& p = route.points_m[k];
    EXPECT_TRUE(sim::world::regions_contain(plan.walkable, p)) << "route point " << k << " outside";
    EXPECT_GE(sim::world::nearest_wall_distance_m(plan, p), scene.route.min_wall_clearance_m - 1e-9)
        << "route point " << k << " too close to a wall";
    if (k == 0) continue;
    const Eigen::Vector2d step = p - route.points_m[k - 1];
    EXPECT_LE(step.norm(), 0.05 + 1e-9);
    EXPECT_NEAR(route.arc_length_m[k] - route.arc_length_m[k - 1], step.norm(), 1e-9);
    if (step.norm() > 1e-3) {
      const Eigen::Vector2d h(std::cos(route.heading_rad[k]), std::sin(route.heading_rad[k]));
      EXPECT_GT(h.dot(step.normalized()), std::cos(0.1)) << "heading off the direction of travel";
    }
  }
  EXPECT_EQ(route.points_m.front(), scene.find_node(scene.route.nodes.front())->position_m);
  EXPECT_EQ(route.points_m.back(), scene.find_node(scene.route.nodes.back())->position_m);
}

}  // namespace

void expect_plan_invariants(const sim::scene::Scene& scene, const sim::world::World& world) {
  const sim::world::FloorPlan& plan = world.plan;
  ASSERT_EQ(plan.walkable.size(), 1u) << "walkable space must be one connected piece";
  ASSERT_FALSE(plan.wall_faces.empty());
  int walkable_piece = -1;
  expect_free_space_reachable(world, walkable_piece);
  if (::testing::Test::HasFatalFailure()) return;
  expect_rooms_apart(plan);
  if (::testing::Test::HasFatalFailure()) return;
  expect_wall_faces(scene, plan);
  if (::testing::Test::HasFatalFailure()) return;
  expect_doors(plan, walkable_piece);
  if (::testing::Test::HasFatalFailure()) return;
  expect_route(scene, world);
}

void expect_mesh_invariants(const sim::world::World& world) {
  const sim::world::Mesh& mesh = world.mesh;
  const sim::world::FloorPlan& plan = world.plan;
  ASSERT_FALSE(mesh.triangles.empty());
  ASSERT_EQ(mesh.normals.size(), mesh.positions_m.size());
  ASSERT_EQ(mesh.uv_m.size(), mesh.positions_m.size());

  using Key = std::tuple<long long, long long, long long>;
  auto key = [](const Eigen::Vector3f& p) {
    return Key(std::llround(p.x() * 1e5), std::llround(p.y() * 1e5), std::llround(p.z() * 1e5));
  };
  std::map<std::pair<Key, Key>, int> directed;
  int bad_area = 0, bad_normal = 0, bad_side = 0, bad_uv = 0;
  for (const sim::world::Triangle& t : mesh.triangles) {
    const Eigen::Vector3f& p0 = mesh.positions_m[t.v[0]];
    const Eigen::Vector3f& p1 = mesh.positions_m[t.v[1]];
    const Eigen::Vector3f& p2 = mesh.positions_m[t.v[2]];
    const Eigen::Vector3d cross = (p1 - p0).cross(p2 - p0).cast<double>();
    if (0.5 * cross.norm() <= 1e-8) ++bad_area;
    // Stored normals: unit, the same at all three corners, agreeing with the winding.
    const Eigen::Vector3d n = mesh.normals[t.v[0]].cast<double>();
    if (std::abs(n.norm() - 1) > 1e-5 || mesh.normals[t.v[1]] != mesh.normals[t.v[0]] ||
        mesh.normals[t.v[2]] != mesh.normals[t.v[0]] || cross.normalized().dot(n) < 0.999)
      ++bad_normal;
    const bool solid = t.surface == sim::world::SurfaceKind::kWall ||
                       t.surface == sim::world::SurfaceKind::kDoor ||
                       t.surface == sim::world::SurfaceKind::kWallTop;
    if (solid) {
      const Eigen::Vector3f* p[3] = {&p0, &p1, &p2};
      for (int i = 0; i < 3; ++i) ++directed[{key(*p[i]), key(*p[(i + 1) % 3])}];
    }
    if (t.surface == sim::world::SurfaceKind::kWall ||
        t.surface == sim::world::SurfaceKind::kDoor) {
      // A point just in front of the face is out of the wall, one just behind it is in.
      const Eigen::Vector2d c = ((p0 + p1 + p2) / 3).head<2>().cast<double>();
      const Eigen::Vector2d n2 = n.head<2>();
      if (sim::world::regions_contain(plan.walls, c + 0.01 * n2) ||
          !sim::world::regions_contain(plan.walls, c - 0.01 * n2))
        ++bad_side;
      // Texture coordinates in metres: uv distances equal 3-D distances.
      for (int i = 0; i < 3; ++i) {
        const int a = t.v[i], b = t.v[(i + 1) % 3];
        const double d3 = (mesh.positions_m[a] - mesh.positions_m[b]).norm();
        const double duv = (mesh.uv_m[a] - mesh.uv_m[b]).norm();
        if (std::abs(d3 - duv) > 1e-3) ++bad_uv;
      }
    }
    if (t.surface == sim::world::SurfaceKind::kFloor && n.z() < 0.999) ++bad_normal;
    if (t.surface == sim::world::SurfaceKind::kCeiling && n.z() > -0.999) ++bad_normal;
  }
  EXPECT_EQ(bad_area, 0) << "degenerate triangles";
  EXPECT_EQ(bad_normal, 0) << "normals inconsistent with winding";
  EXPECT_EQ(bad_side, 0) << "wall triangles facing into their wall";
  EXPECT_EQ(bad_uv, 0) << "wall texture coordinates not in metres";
  // Closed and consistently oriented: every directed edge once, and its reverse once.
  int open_edges = 0;
  for (const auto& [edge, count] : directed) {
    auto reverse = directed.find({edge.second, edge.first});
    if (count != 1 || reverse == directed.end() || reverse->second != 1) ++open_edges;
  }
  EXPECT_EQ(open_edges, 0) << "wall solids not closed";
}

}  // namespace wifislam::test
