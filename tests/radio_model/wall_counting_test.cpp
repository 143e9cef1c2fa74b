// The counting rule of embree_wall_scene.hpp on hand-built geometry laid out as the world's mesh
// is: vertical faces along the outline of each wall solid, normals toward free space, one wall_id
// per straight wall piece (so a junction or a door leaf joins pieces of different ids), no caps.
// Each case says what the old rule (one crossing per distinct wall_id hit) counted.
#include <gtest/gtest.h>

#include <vector>

#include "radio_model/access_point.hpp"
#include "radio_model/embree_wall_scene.hpp"
#include "radio_model/propagation_model.hpp"
#include "tests/radio_model/test_walls.hpp"

namespace wifislam::radio_model {
namespace {

using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

constexpr float kHeightM = 2.8f;

// A vertical face over a -> b between heights z0 and z1, with the wall on its right and free
// space (the normal) on its left, as the plan's faces are oriented.
void add_face(WallMesh& mesh, const V2& a, const V2& b, float z0, float z1, WallMaterial material,
              int wall_id) {
  using V = Eigen::Vector3f;
  const V pa(static_cast<float>(a.x()), static_cast<float>(a.y()), 0.0f);
  const V pb(static_cast<float>(b.x()), static_cast<float>(b.y()), 0.0f);
  test::add_quad(mesh, pa + V(0, 0, z0), pa + V(0, 0, z1), pb + V(0, 0, z1), pb + V(0, 0, z0),
                 material, wall_id);
}

struct OutlineFace {
  V2 a, b;
  WallMaterial material;
  int wall_id;
};

WallMesh outline_solid(const std::vector<OutlineFace>& faces) {
  WallMesh mesh;
  for (const OutlineFace& f : faces)
    add_face(mesh, f.a, f.b, 0.0f, kHeightM, f.material, f.wall_id);
  return mesh;
}

// A T: bar x in [0, 10], y in [-0.1, 0.1] (brick, wall 1); stem x in [4.9, 5.1] up to y = 5
// (plasterboard, wall 2). The outline runs clockwise, so the solid is on each face's right.
WallMesh t_junction() {
  const auto brick = WallMaterial::kBrick, plaster = WallMaterial::kPlasterboard;
  return outline_solid({{{0, -0.1}, {0, 0.1}, brick, 1},
                        {{0, 0.1}, {4.9, 0.1}, brick, 1},
                        {{4.9, 0.1}, {4.9, 5}, plaster, 2},
                        {{4.9, 5}, {5.1, 5}, plaster, 2},
                        {{5.1, 5}, {5.1, 0.1}, plaster, 2},
                        {{5.1, 0.1}, {10, 0.1}, brick, 1},
                        {{10, 0.1}, {10, -0.1}, brick, 1},
                        {{10, -0.1}, {0, -0.1}, brick, 1}});
}

TEST(WallCounting, ARayThroughATJunctionCrossesOneWallOfBothMaterials) {
  const EmbreeWallScene scene(t_junction());
  // Enters the stem's side at (4.9, 0.15) and leaves the bar's underside at (5.07, -0.1): one
  // stretch of material (the old rule counted walls 2 and 1).
  const auto crossed = scene.walls_crossed(V3(3, 3, 1), V3(7, -3, 1));
  ASSERT_EQ(crossed.size(), 1u);
  EXPECT_EQ(crossed[0].wall_id, 2);
  EXPECT_EQ(crossed[0].material, WallMaterial::kPlasterboard);
  EXPECT_EQ(crossed[0].exit_material, WallMaterial::kBrick);
  EXPECT_NEAR(crossed[0].length_m, std::hypot(0.1667, 0.25), 0.01);
  // Away from the junction each piece is one wall of its own material.
  const auto bar = scene.walls_crossed(V3(2, 3, 1), V3(2, -3, 1));
  ASSERT_EQ(bar.size(), 1u);
  EXPECT_EQ(bar[0].material, WallMaterial::kBrick);
  EXPECT_EQ(bar[0].exit_material, WallMaterial::kBrick);
  EXPECT_NEAR(bar[0].length_m, 0.2, 1e-4);
  const auto stem = scene.walls_crossed(V3(3, 3, 1), V3(7, 3, 1));
  ASSERT_EQ(stem.size(), 1u);
  EXPECT_EQ(stem[0].material, WallMaterial::kPlasterboard);
  // The two-material crossing costs half a wall of each: between one brick and one plasterboard
  // wall, and less than the two the old rule charged.
  MacAllocator macs(3);
  PropagationOptions quiet;
  quiet.shadowing_sigma_db = 0.0;
  PropagationModel model(t_junction(), {-5, -5}, {15, 10},
                         {make_access_point(0, V3(3, 3, 1), 20.0, 1, 3, macs)}, quiet, 3);
  const RadioLink link = model.link(0, V3(7, -3, 1));
  EXPECT_DOUBLE_EQ(link.wall_count(), 1.0);
  EXPECT_DOUBLE_EQ(link.walls_per_material[material_index(WallMaterial::kBrick)], 0.5);
  EXPECT_DOUBLE_EQ(link.walls_per_material[material_index(WallMaterial::kPlasterboard)], 0.5);
}

// A closed door as the world builds it: one wall solid x in [5, 5.15] whose faces are cut at the
// door's edges, the leaf (|y| < 0.45, up to 2.1 m) a wall piece of its own (wood, wall 3), the
// faces beside it the wall (brick, wall 1), the lintel above the leaf part of the leaf's piece.
WallMesh closed_door() {
  WallMesh mesh;
  const auto brick = WallMaterial::kBrick, wood = WallMaterial::kWoodDoor;
  const double x0 = 5.0, x1 = 5.15, d = 0.45, L = 10.0;
  // Front (x = 5, facing -x): walking towards +y keeps the wall (larger x) on the right.
  add_face(mesh, {x0, -L}, {x0, -d}, 0.0f, kHeightM, brick, 1);
  add_face(mesh, {x0, -d}, {x0, d}, 0.0f, 2.1f, wood, 3);
  add_face(mesh, {x0, -d}, {x0, d}, 2.1f, kHeightM, brick, 3);
  add_face(mesh, {x0, d}, {x0, L}, 0.0f, kHeightM, brick, 1);
  // Back (x = 5.15, facing +x), walked towards -y.
  add_face(mesh, {x1, L}, {x1, d}, 0.0f, kHeightM, brick, 1);
  add_face(mesh, {x1, d}, {x1, -d}, 0.0f, 2.1f, wood, 3);
  add_face(mesh, {x1, d}, {x1, -d}, 2.1f, kHeightM, brick, 3);
  add_face(mesh, {x1, -d}, {x1, -L}, 0.0f, kHeightM, brick, 1);
  // Ends.
  add_face(mesh, {x0, L}, {x1, L}, 0.0f, kHeightM, brick, 1);
  add_face(mesh, {x1, -L}, {x0, -L}, 0.0f, kHeightM, brick, 1);
  return mesh;
}

TEST(WallCounting, ARayThroughTheEdgeOfADoorLeafCrossesOneWall) {
  const EmbreeWallScene scene(closed_door());
  // Through the leaf alone: one wooden wall.
  const auto leaf = scene.walls_crossed(V3(0, 0, 1), V3(10, 0.2, 1));
  ASSERT_EQ(leaf.size(), 1u);
  EXPECT_EQ(leaf[0].material, WallMaterial::kWoodDoor);
  EXPECT_EQ(leaf[0].exit_material, WallMaterial::kWoodDoor);
  // Enters the leaf at y = 0.40 and leaves beside it at y = 0.50: one wall, wood then brick (the
  // old rule counted the leaf and the wall: 12 dB instead of 6 at 2.4 GHz).
  const double slope = 0.1 / 0.15;
  const auto edge = scene.walls_crossed(V3(0, 0.40 - 5 * slope, 1), V3(10, 0.40 + 5 * slope, 1));
  ASSERT_EQ(edge.size(), 1u);
  EXPECT_EQ(edge[0].material, WallMaterial::kWoodDoor);
  EXPECT_EQ(edge[0].exit_material, WallMaterial::kBrick);
  EXPECT_NEAR(edge[0].distance_m, std::hypot(5.0, 5 * slope), 0.01);
  // Above the leaf: the lintel, one brick wall.
  const auto lintel = scene.walls_crossed(V3(0, 0, 2.5), V3(10, 0.1, 2.5));
  ASSERT_EQ(lintel.size(), 1u);
  EXPECT_EQ(lintel[0].material, WallMaterial::kBrick);
}

TEST(WallCounting, ARayRunningInsideAWallAlongItsLengthCrossesItOnce) {
  WallMesh mesh;
  test::add_box(mesh, {0, -0.1f, 0}, {10, 0.1f, kHeightM}, WallMaterial::kConcrete, 4);
  const EmbreeWallScene scene(mesh);
  const auto crossed = scene.walls_crossed(V3(-1, 0, 1), V3(11, 0.05, 1));
  ASSERT_EQ(crossed.size(), 1u);
  EXPECT_NEAR(crossed[0].distance_m, 1.0, 1e-3);
  EXPECT_NEAR(crossed[0].length_m, 10.0, 1e-3);
}

TEST(WallCounting, GrazingACornerIsATouchAndGrazingAFaceCrossesAtMostOneWall) {
  WallMesh mesh;
  test::add_box(mesh, {2, 0, 0}, {3, 1, kHeightM}, WallMaterial::kBrick, 5);
  const EmbreeWallScene scene(mesh);
  // Through the corner (2, 0) and nowhere else inside the box (the old rule counted one wall).
  EXPECT_TRUE(scene.walls_crossed(V3(1, 1, 1), V3(3, -1, 1)).empty());
  // A millimetre outside the face y = 0, along it: nothing; a millimetre inside: one wall, 1 m.
  EXPECT_TRUE(scene.walls_crossed(V3(1, -1e-3, 1), V3(4, -1e-3, 1)).empty());
  const auto inside = scene.walls_crossed(V3(1, 1e-3, 1), V3(4, 1e-3, 1));
  ASSERT_EQ(inside.size(), 1u);
  EXPECT_NEAR(inside[0].length_m, 1.0, 1e-3);
  // Exactly in the face's plane the ray meets only the edges of the faces across it: at most one
  // wall, never two.
  EXPECT_LE(scene.walls_crossed(V3(1, 0, 1), V3(4, 0, 1)).size(), 1u);
}

TEST(WallCounting, TouchingSolidsAreOneStretchOfMaterial) {
  // Two boxes side by side (a lintel against its jamb, the end of one wall against another): the
  // faces where they touch coincide with opposite normals.
  WallMesh mesh;
  test::add_box(mesh, {2, -1, 0}, {2.2f, 0, kHeightM}, WallMaterial::kBrick, 6);
  test::add_box(mesh, {2, 0, 0}, {2.2f, 1, kHeightM}, WallMaterial::kPlasterboard, 7);
  const EmbreeWallScene scene(mesh);
  // Enters the first at (2, -0.1), passes where they touch at (2.1, 0), leaves the second at
  // (2.2, 0.1) (the old rule counted walls 6 and 7).
  const auto crossed = scene.walls_crossed(V3(0, -2.1, 1), V3(4, 1.9, 1));
  ASSERT_EQ(crossed.size(), 1u);
  EXPECT_EQ(crossed[0].material, WallMaterial::kBrick);
  EXPECT_EQ(crossed[0].exit_material, WallMaterial::kPlasterboard);
  // Two separate walls stay two.
  WallMesh apart;
  test::add_box(apart, {2, -1, 0}, {2.2f, 1, kHeightM}, WallMaterial::kBrick, 8);
  test::add_box(apart, {3, -1, 0}, {3.2f, 1, kHeightM}, WallMaterial::kBrick, 9);
  EXPECT_EQ(EmbreeWallScene(apart).walls_crossed(V3(0, 0, 1), V3(4, 0.1, 1)).size(), 2u);
}

TEST(WallCounting, ASegmentStartingInsideAWallCrossesIt) {
  WallMesh mesh;
  test::add_box(mesh, {2, -1, 0}, {2.5f, 1, kHeightM}, WallMaterial::kConcrete, 10);
  const EmbreeWallScene scene(mesh);
  const auto crossed = scene.walls_crossed(V3(2.2, 0, 1), V3(6, 0, 1));
  ASSERT_EQ(crossed.size(), 1u);
  EXPECT_EQ(crossed[0].wall_id, 10);
  // From the segment's start (which is excluded by a millimetre) to the face at x = 2.5.
  EXPECT_NEAR(crossed[0].length_m, 0.299, 1e-4);
}

}  // namespace
}  // namespace wifislam::radio_model
