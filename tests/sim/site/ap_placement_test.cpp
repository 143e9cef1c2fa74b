#include <gtest/gtest.h>

#include <set>

#include "core/error.hpp"
#include "sim/site/ap_placement.hpp"
#include "sim/world/plan_queries.hpp"
#include "tests/sim/site/test_plan.hpp"

namespace wifislam::sim {
namespace {

TEST(ApPlacement, RoomsPlacementPutsMostApsInRoomsOffTheCorridor) {
  const world::FloorPlan plan = test::corridor_with_rooms(7);
  scene::AccessPoints spec;
  spec.placement = scene::ApPlacement::kRooms;
  spec.count = 6;
  spec.min_spacing_m = 3.0;
  const auto pos = site::place_access_point_positions(spec, plan, 42);
  ASSERT_EQ(pos.size(), 6u);
  int in_rooms = 0;
  for (const auto& p : pos) {
    EXPECT_TRUE(world::regions_contain(plan.free_space, p.head<2>()));
    EXPECT_DOUBLE_EQ(p.z(), spec.height_m);
    EXPECT_GE(world::nearest_wall_distance_m(plan, p.head<2>()), 0.4 - 1e-9);
    bool room = false;
    for (const world::Room& r : plan.rooms) room |= world::ring_contains(r.polygon_m, p.head<2>());
    in_rooms += room;
  }
  EXPECT_EQ(in_rooms, 5);  // 6 - 6/4
  for (std::size_t i = 0; i < pos.size(); ++i)
    for (std::size_t j = i + 1; j < pos.size(); ++j)
      EXPECT_GE((pos[i] - pos[j]).norm(), spec.min_spacing_m);
  EXPECT_EQ(site::place_access_point_positions(spec, plan, 42), pos);  // deterministic
  EXPECT_NE(site::place_access_point_positions(spec, plan, 43), pos);
}

TEST(ApPlacement, RandomGridColinearAndExplicit) {
  const world::FloorPlan plan = test::corridor_with_rooms(7);
  scene::AccessPoints spec;
  spec.count = 5;
  spec.placement = scene::ApPlacement::kRandom;
  const auto random = site::place_access_point_positions(spec, plan, 3);
  ASSERT_EQ(random.size(), 5u);
  for (const auto& p : random) EXPECT_TRUE(world::regions_contain(plan.free_space, p.head<2>()));

  spec.placement = scene::ApPlacement::kGrid;
  spec.count = 4;
  const auto grid = site::place_access_point_positions(spec, plan, 3);
  ASSERT_EQ(grid.size(), 4u);
  // A 30 m x 6 m plan takes a 4 x 1 grid: x near 3.8, 11.4, 19, 26.6.
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(grid[i].x(), -0.2 + (i + 0.5) * 30.4 / 4, 0.8);

  spec.placement = scene::ApPlacement::kColinear;
  spec.count = 3;
  spec.line_from_m = {1, 1};
  spec.line_to_m = {21, 1};
  const auto line = site::place_access_point_positions(spec, plan, 3);
  ASSERT_EQ(line.size(), 3u);
  EXPECT_NEAR(line[1].x(), 11.0, 1e-12);
  spec.line_to_m = spec.line_from_m;
  EXPECT_THROW(site::place_access_point_positions(spec, plan, 3), InvalidInputError);

  scene::Scene scene;
  scene.access_points.placement = scene::ApPlacement::kExplicit;
  scene.access_points.explicit_list = {{Eigen::Vector3d(1, 1, 2), std::nullopt},
                                       {Eigen::Vector3d(5, 1, 2), 15.0}};
  const auto aps = site::make_access_points(scene, plan);
  ASSERT_EQ(aps.size(), 2u);
  EXPECT_EQ(aps[1].position_m, Eigen::Vector3d(5, 1, 2));
  EXPECT_EQ(aps[0].tx_power_dbm, scene.access_points.tx_power_dbm);
  EXPECT_EQ(aps[1].tx_power_dbm, 15.0);
  EXPECT_EQ(aps[0].bssids.size(), 2u * scene.access_points.ssids_per_radio);
}

}  // namespace
}  // namespace wifislam::sim
