#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.hpp"
#include "sim/world/box_grid.hpp"
#include "sim/world/floor_plan_builder.hpp"
#include "sim/world/plan_queries.hpp"
#include "sim/world/region_locator.hpp"
#include "sim/world/wall_face_grid.hpp"
#include "sim/world/world_generator.hpp"
#include "tests/sim/world/world_test_support.hpp"

namespace wifislam::sim {
namespace {

const world::WallFace2& face_nearest(const world::FloorPlan& plan, const Eigen::Vector2d& p) {
  int index = -1;
  world::nearest_wall_distance_m(plan, p, &index);
  return plan.wall_faces.at(index);
}

TEST(FloorPlan, SquareLoopWithClosedOutsideDoorsMeetsInvariants) {
  const scene::Scene scene = test::square_loop_scene(14.0, 2.0, false);
  const world::World world = world::generate_world(scene);
  test::expect_plan_invariants(scene, world);
}

TEST(FloorPlan, SquareLoopWithOpenOutsideDoorsMeetsInvariants) {
  const scene::Scene scene = test::square_loop_scene(14.0, 2.0, true);
  const world::World world = world::generate_world(scene);
  test::expect_plan_invariants(scene, world);
}

TEST(FloorPlan, RoomsThatWouldOverlapACorridorAreDroppedWhole) {
  const scene::Scene scene = test::square_loop_scene(14.0, 2.0, false);
  const world::FloorPlan plan = world::build_floor_plan(scene);
  // Outside: 4 corridors x 4 rooms of 3 m in [1, 13]. Inside: rooms of 3.5 m in [0, 14]; the
  // first and last run into the west and east corridors.
  int inside = 0;
  for (const world::Room& r : plan.rooms)
    inside += r.material == radio_model::WallMaterial::kConcrete;
  EXPECT_EQ(plan.rooms.size(), 18u);
  EXPECT_EQ(inside, 2);
  EXPECT_EQ(plan.doors.size(), plan.rooms.size());
}

TEST(FloorPlan, OneWallOfTheSceneThicknessSeparatesRoomsAndCorridors) {
  const scene::Scene scene = test::square_loop_scene();
  const world::FloorPlan plan = world::build_floor_plan(scene);
  const double t = scene.building.wall_thickness_m;
  std::map<int, std::vector<const world::WallFace2*>> by_wall;
  for (const world::WallFace2& f : plan.wall_faces) by_wall[f.wall_id].push_back(&f);
  for (const auto& [id, faces] : by_wall) {
    // A physical wall has two sides; faces of one wall that face each other are t apart.
    EXPECT_GE(faces.size(), 2u) << "wall " << id << " has one face";
    int opposite_pairs = 0;
    for (const world::WallFace2* f : faces) {
      const Eigen::Vector2d d = (f->b_m - f->a_m).normalized();
      for (const world::WallFace2* g : faces) {
        const Eigen::Vector2d e = (g->b_m - g->a_m).normalized();
        if (d.dot(e) > -1 + 1e-9) continue;
        const Eigen::Vector2d right(d.y(), -d.x());
        EXPECT_NEAR((g->a_m - f->a_m).dot(right), t, 1e-9) << "wall " << id;
        ++opposite_pairs;
      }
    }
    EXPECT_GT(opposite_pairs, 0) << "wall " << id << " has no two opposite faces";
  }
  // Each room's door side: the corridor face and the room face in front of it share a wall.
  for (const world::Door& d : plan.doors) {
    const Eigen::Vector2d n(-d.along_wall.y(), d.along_wall.x());
    const Eigen::Vector2d beside = d.center_m + (0.5 * d.width_m + 0.3) * d.along_wall;
    const world::WallFace2& a = face_nearest(plan, beside + (0.5 * t + 0.01) * n);
    const world::WallFace2& b = face_nearest(plan, beside - (0.5 * t + 0.01) * n);
    EXPECT_EQ(a.wall_id, b.wall_id);
  }
}

TEST(FloorPlan, WallMaterialsFollowWhatTheWallBounds) {
  const scene::Scene scene = test::square_loop_scene();
  const world::FloorPlan plan = world::build_floor_plan(scene);
  // South corridor (y in [-1, 1]): its north wall at x = 6.5 fronts an inside room (concrete),
  // at x = 1.5 it fronts nothing (corridor plasterboard); its south wall fronts brick rooms.
  EXPECT_EQ(face_nearest(plan, {6.5, 0.99}).material, radio_model::WallMaterial::kConcrete);
  EXPECT_EQ(face_nearest(plan, {1.5, 0.99}).material, radio_model::WallMaterial::kPlasterboard);
  EXPECT_EQ(face_nearest(plan, {6.5, -0.99}).material, radio_model::WallMaterial::kBrick);
  // The wall's far side has the same wall id and material.
  const world::WallFace2& near = face_nearest(plan, {6.5, 0.99});
  const world::WallFace2& far = face_nearest(plan, {6.5, 1.16});
  EXPECT_EQ(near.wall_id, far.wall_id);
  EXPECT_EQ(near.material, far.material);
}

TEST(FloorPlan, ClosedDoorLeafIsItsOwnWoodenWall) {
  const scene::Scene scene = test::square_loop_scene(14.0, 2.0, false);
  const world::FloorPlan plan = world::build_floor_plan(scene);
  int closed = 0;
  for (const world::Door& d : plan.doors) {
    if (d.open) continue;
    ++closed;
    const Eigen::Vector2d n(-d.along_wall.y(), d.along_wall.x());
    const double off = 0.5 * d.wall_thickness_m + 0.01;
    const world::WallFace2& a = face_nearest(plan, d.center_m + off * n);
    const world::WallFace2& b = face_nearest(plan, d.center_m - off * n);
    EXPECT_EQ(a.material, radio_model::WallMaterial::kWoodDoor);
    EXPECT_EQ(a.wall_id, b.wall_id);
    // Beside the door the wall is a different one.
    const world::WallFace2& beside =
        face_nearest(plan, d.center_m + (0.5 * d.width_m + 0.2) * d.along_wall + off * n);
    EXPECT_NE(beside.wall_id, a.wall_id);
    EXPECT_NE(beside.material, radio_model::WallMaterial::kWoodDoor);
  }
  EXPECT_EQ(closed, 16);
}

TEST(FloorPlan, DisconnectedCorridorsAreRejected) {
  scene::Scene scene;
  scene.nodes = {{"A", {0, 0}}, {"B", {5, 0}}, {"C", {0, 10}}, {"D", {5, 10}}};
  scene::Corridor ab;
  ab.id = "ab", ab.from = "A", ab.to = "B";
  scene::Corridor cd;
  cd.id = "cd", cd.from = "C", cd.to = "D";
  scene.corridors = {ab, cd};
  scene.route.nodes = {"A", "B"};
  try {
    world::build_floor_plan(scene);
    FAIL() << "expected InvalidInputError";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("2 separate pieces"), std::string::npos) << e.what();
  }
}

TEST(FloorPlan, OpenAreaWithPillarsIsFreeSpaceAroundSolidPillars) {
  scene::Scene scene;
  scene.nodes = {{"A", {2, 2}}, {"B", {18, 2}}};
  scene::Corridor ab;
  ab.id = "track", ab.from = "A", ab.to = "B", ab.width_m = 2.0;
  scene.corridors = {ab};
  scene::OpenArea hall;
  hall.id = "hall";
  hall.polygon_m = {{0, 0}, {20, 0}, {20, 10}, {0, 10}};
  hall.pillars = {{{10, 6}, 0.8}};
  scene.open_areas = {hall};
  scene.route.nodes = {"A", "B"};
  const world::World world = world::generate_world(scene);
  test::expect_plan_invariants(scene, world);
  EXPECT_NEAR(world::regions_area_m2(world.plan.free_space), 200.0 - 0.64, 1e-9);
  EXPECT_FALSE(world::regions_contain(world.plan.free_space, {10, 6}));
  EXPECT_TRUE(world::regions_contain(world.plan.walls, {10, 6}));
  // The pillar's four faces are one wall, in the hall's material.
  const world::WallFace2& f1 = face_nearest(world.plan, {10.41, 6});
  const world::WallFace2& f2 = face_nearest(world.plan, {10, 6.41});
  EXPECT_EQ(f1.wall_id, f2.wall_id);
  EXPECT_EQ(f1.material, radio_model::WallMaterial::kConcrete);
  EXPECT_FALSE(world.plan.lights.empty());
}

// The grid answers "is a wall closer than r?" exactly as scanning every face does: the same
// distance below r, infinity at or above it. Points on a fine lattice over the whole plan,
// including inside walls and outside the building, with several radii.
TEST(FloorPlan, WallFaceGridAgreesWithTheFullScan) {
  const scene::Scene scene = test::square_loop_scene(14.0);
  const world::FloorPlan plan = world::build_floor_plan(scene);
  ASSERT_GT(plan.wall_faces.size(), 20u);
  for (const double radius : {0.3, 0.4, 1.0, 2.5}) {
    const world::WallFaceGrid grid(plan, radius);
    int near = 0;
    for (double y = plan.bounds_min_m.y() - 2.0; y < plan.bounds_max_m.y() + 2.0; y += 0.173) {
      for (double x = plan.bounds_min_m.x() - 2.0; x < plan.bounds_max_m.x() + 2.0; x += 0.191) {
        const Eigen::Vector2d p(x, y);
        const double full = world::nearest_wall_distance_m(plan, p);
        const double fast = grid.nearest_within_m(p, radius);
        if (full < radius) {
          ++near;
          ASSERT_EQ(fast, full) << "at " << x << ", " << y << " radius " << radius;
        } else {
          ASSERT_TRUE(std::isinf(fast)) << "at " << x << ", " << y << " radius " << radius;
        }
      }
    }
    EXPECT_GT(near, 1000) << radius;
  }
}

// The region locator answers regions_find's question with regions_find's answer, on the free
// space, the walkable space and the wall solids (rings with holes) of a plan, on a lattice that
// includes points outside the building and points on lattice lines through ring vertices.
TEST(FloorPlan, RegionLocatorAgreesWithTheFullScan) {
  const scene::Scene scene = test::square_loop_scene(14.0);
  const world::FloorPlan plan = world::build_floor_plan(scene);
  for (const auto* regions : {&plan.free_space, &plan.walkable, &plan.walls}) {
    ASSERT_FALSE(regions->empty());
    for (const double band_m : {0.25, 1.0, 7.0}) {
      const world::RegionLocator locator(*regions, band_m);
      int inside = 0;
      for (double y = plan.bounds_min_m.y() - 2.0; y < plan.bounds_max_m.y() + 2.0; y += 0.1) {
        for (double x = plan.bounds_min_m.x() - 2.0; x < plan.bounds_max_m.x() + 2.0; x += 0.137) {
          const Eigen::Vector2d p(x, y);
          const int full = world::regions_find(*regions, p);
          ASSERT_EQ(locator.find(p), full) << "at " << x << ", " << y << " band " << band_m;
          inside += full >= 0;
        }
      }
      EXPECT_GT(inside, 500) << band_m;
    }
  }
}

// Every item whose box overlaps the query box is among the candidates, sorted and once each.
TEST(FloorPlan, BoxGridFindsEveryOverlappingBoxInIndexOrder) {
  const scene::Scene scene = test::square_loop_scene(14.0);
  const world::FloorPlan plan = world::build_floor_plan(scene);
  world::BoxGrid grid(1.5);
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> boxes;
  for (const world::WallFace2& f : plan.wall_faces) {
    boxes.emplace_back(f.a_m.cwiseMin(f.b_m), f.a_m.cwiseMax(f.b_m));
    grid.add(static_cast<int>(boxes.size()) - 1, boxes.back().first, boxes.back().second);
  }
  for (double y = plan.bounds_min_m.y() - 1.0; y < plan.bounds_max_m.y() + 1.0; y += 0.7) {
    for (double x = plan.bounds_min_m.x() - 1.0; x < plan.bounds_max_m.x() + 1.0; x += 0.9) {
      const Eigen::Vector2d lo(x, y), hi(x + 0.4, y + 2.0);
      const std::vector<int> found = grid.near(lo, hi);
      ASSERT_TRUE(std::is_sorted(found.begin(), found.end()));
      ASSERT_EQ(std::adjacent_find(found.begin(), found.end()), found.end());
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        const bool overlaps = boxes[i].first.x() <= hi.x() && lo.x() <= boxes[i].second.x() &&
                              boxes[i].first.y() <= hi.y() && lo.y() <= boxes[i].second.y();
        if (overlaps) {
          ASSERT_TRUE(std::binary_search(found.begin(), found.end(), static_cast<int>(i)))
              << "face " << i << " at " << x << ", " << y;
        }
      }
    }
  }
}

}  // namespace
}  // namespace wifislam::sim
