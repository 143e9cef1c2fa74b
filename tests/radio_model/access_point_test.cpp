#include <gtest/gtest.h>

#include <set>

#include "core/error.hpp"
#include "radio_model/access_point.hpp"
#include "radio_model/ap_placement.hpp"
#include "sim/world/plan_queries.hpp"
#include "tests/radio_model/test_plan.hpp"

namespace wifislam::radio_model {
namespace {

std::vector<AccessPoint> many_aps(std::uint64_t seed, int count, int ssids) {
  MacAllocator macs(seed);
  std::vector<AccessPoint> aps;
  for (int i = 0; i < count; ++i)
    aps.push_back(make_access_point(i, Eigen::Vector3d(i, 0, 2.5), 20.0, ssids, seed, macs));
  return aps;
}

TEST(AccessPoints, AllBssidsOfOneApDifferOnlyInTheLastNibble) {
  for (const AccessPoint& ap : many_aps(11, 300, 3)) {
    ASSERT_EQ(ap.bssids.size(), 6u);
    std::set<std::uint64_t> macs;
    for (const Bssid& b : ap.bssids) {
      EXPECT_EQ(b.mac.without_last_nibble(), ap.base_mac());
      EXPECT_TRUE(macs.insert(b.mac.value).second) << "duplicate BSSID within an AP";
      const std::uint64_t nibble = b.mac.value & 0xF;
      if (b.band == RadioBand::k2_4GHz)
        EXPECT_LT(nibble, 8u);
      else
        EXPECT_GE(nibble, 8u);
      EXPECT_EQ(b.frequency_khz, channel_frequency_khz(b.band, b.channel));
    }
    // Unicast, locally administered.
    EXPECT_EQ((ap.base_mac().value >> 40) & 0x3, 0x2u);
  }
}

TEST(AccessPoints, DifferentApsNeverCollideEvenAfterAggregation) {
  for (std::uint64_t seed : {1u, 2u, 99u}) {
    std::set<std::uint64_t> bases;
    for (const AccessPoint& ap : many_aps(seed, 2000, 8))
      EXPECT_TRUE(bases.insert(ap.base_mac().value).second) << "AP " << ap.id;
  }
}

TEST(AccessPoints, MacsAreDeterministicFromTheSeed) {
  const auto a = many_aps(5, 20, 3), b = many_aps(5, 20, 3), c = many_aps(6, 20, 3);
  int differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t k = 0; k < a[i].bssids.size(); ++k) {
      EXPECT_EQ(a[i].bssids[k].mac, b[i].bssids[k].mac);
      EXPECT_EQ(a[i].bssids[k].channel, b[i].bssids[k].channel);
    }
    differ += a[i].base_mac() != c[i].base_mac();
  }
  EXPECT_EQ(differ, 20);
}

TEST(AccessPoints, RejectsMoreSsidsThanALastNibbleCanHold) {
  MacAllocator macs(1);
  EXPECT_THROW(make_access_point(0, Eigen::Vector3d::Zero(), 20, 9, 1, macs), InvalidInputError);
  EXPECT_THROW(make_access_point(0, Eigen::Vector3d::Zero(), 20, 0, 1, macs), InvalidInputError);
}

TEST(ApPlacement, RoomsPlacementPutsMostApsInRoomsOffTheCorridor) {
  const sim::FloorPlan plan = test::corridor_with_rooms(7);
  sim::AccessPoints spec;
  spec.placement = sim::ApPlacement::kRooms;
  spec.count = 6;
  spec.min_spacing_m = 3.0;
  const auto pos = place_access_point_positions(spec, plan, 42);
  ASSERT_EQ(pos.size(), 6u);
  int in_rooms = 0;
  for (const auto& p : pos) {
    EXPECT_TRUE(sim::regions_contain(plan.free_space, p.head<2>()));
    EXPECT_DOUBLE_EQ(p.z(), spec.height_m);
    EXPECT_GE(sim::nearest_wall_distance_m(plan, p.head<2>()), 0.4 - 1e-9);
    bool room = false;
    for (const sim::Room& r : plan.rooms) room |= sim::ring_contains(r.polygon_m, p.head<2>());
    in_rooms += room;
  }
  EXPECT_EQ(in_rooms, 5);  // 6 - 6/4
  for (std::size_t i = 0; i < pos.size(); ++i)
    for (std::size_t j = i + 1; j < pos.size(); ++j)
      EXPECT_GE((pos[i] - pos[j]).norm(), spec.min_spacing_m);
  EXPECT_EQ(place_access_point_positions(spec, plan, 42), pos);  // deterministic
  EXPECT_NE(place_access_point_positions(spec, plan, 43), pos);
}

TEST(ApPlacement, RandomGridColinearAndExplicit) {
  const sim::FloorPlan plan = test::corridor_with_rooms(7);
  sim::AccessPoints spec;
  spec.count = 5;
  spec.placement = sim::ApPlacement::kRandom;
  const auto random = place_access_point_positions(spec, plan, 3);
  ASSERT_EQ(random.size(), 5u);
  for (const auto& p : random) EXPECT_TRUE(sim::regions_contain(plan.free_space, p.head<2>()));

  spec.placement = sim::ApPlacement::kGrid;
  spec.count = 4;
  const auto grid = place_access_point_positions(spec, plan, 3);
  ASSERT_EQ(grid.size(), 4u);
  // A 30 m x 6 m plan takes a 4 x 1 grid: x near 3.8, 11.4, 19, 26.6.
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(grid[i].x(), -0.2 + (i + 0.5) * 30.4 / 4, 0.8);

  spec.placement = sim::ApPlacement::kColinear;
  spec.count = 3;
  spec.line_from_m = {1, 1};
  spec.line_to_m = {21, 1};
  const auto line = place_access_point_positions(spec, plan, 3);
  ASSERT_EQ(line.size(), 3u);
  EXPECT_NEAR(line[1].x(), 11.0, 1e-12);
  spec.line_to_m = spec.line_from_m;
  EXPECT_THROW(place_access_point_positions(spec, plan, 3), InvalidInputError);

  sim::Scene scene;
  scene.access_points.placement = sim::ApPlacement::kExplicit;
  scene.access_points.explicit_list = {{Eigen::Vector3d(1, 1, 2), std::nullopt},
                                       {Eigen::Vector3d(5, 1, 2), 15.0}};
  const auto aps = make_access_points(scene, plan);
  ASSERT_EQ(aps.size(), 2u);
  EXPECT_EQ(aps[1].position_m, Eigen::Vector3d(5, 1, 2));
  EXPECT_EQ(aps[0].tx_power_dbm, scene.access_points.tx_power_dbm);
  EXPECT_EQ(aps[1].tx_power_dbm, 15.0);
  EXPECT_EQ(aps[0].bssids.size(), 2u * scene.access_points.ssids_per_radio);
}

}  // namespace
}  // namespace wifislam::radio_model
