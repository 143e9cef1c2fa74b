// Radio through floors: an access point on the storey above a floor slab, heard below it. Each
// expectation is an independent calculation from the cited sources, not the model's own tables:
// under itu_walls a concrete slab costs 3GPP TR 38.901's concrete loss, 5 + 4 f_GHz dB; under
// itu_site_general the link costs ITU-R P.1238-7 Table 3's floor penetration factor for offices
// (14 dB at 2.4 GHz, 16 dB at 5.2 GHz for one floor). Real Embree rays throughout.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "radio_model/embree_wall_scene.hpp"
#include "radio_model/propagation_model.hpp"
#include "radio_model/radio_map.hpp"
#include "tests/radio_model/test_walls.hpp"

namespace wifislam::radio_model {
namespace {

// Storeys 3.2 m apart: a 0.2 m concrete slab from z = 3.0 to 3.2, and one more from 6.2 to 6.4.
constexpr float kSlabBottomM = 3.0f, kSlabTopM = 3.2f, kStoreyM = 3.2f;

WallMesh storeys(int slabs) {
  WallMesh mesh;
  for (int k = 0; k < slabs; ++k)
    test::add_slab(mesh, {-20.0f, -20.0f}, {20.0f, 20.0f}, kSlabBottomM + k * kStoreyM,
                   kSlabTopM + k * kStoreyM, WallMaterial::kConcrete, 100 + k);
  return mesh;
}

std::vector<AccessPoint> one_ap(const Eigen::Vector3d& at) {
  MacAllocator macs(11);
  return {make_access_point(0, at, 20.0, 2, 11, macs)};
}

PropagationOptions noiseless(PathLossModel model) {
  PropagationOptions options;
  options.model = model;
  options.environment = RadioEnvironment::kOffice;
  options.shadowing_sigma_db = 0.0;
  return options;
}

PropagationModel model_of(const WallMesh& mesh, const Eigen::Vector3d& ap, PathLossModel kind) {
  return PropagationModel(mesh, {-20, -20}, {20, 20}, one_ap(ap), noiseless(kind), 11);
}

double tr38901_concrete_db(double frequency_mhz) { return 5.0 + 4.0 * frequency_mhz * 1e-3; }
double p1238_office_one_floor_db(double frequency_mhz) {
  return frequency_mhz < 4000.0 ? 14.0 : 16.0;
}

const Eigen::Vector3d kUpstairsAp(0.0, 0.0, 5.7);  // 2.5 m above the first slab's top
const Eigen::Vector3d kDownstairs(6.0, 2.0, 1.2);

TEST(FloorSlab, UnderItuWallsASlabCostsExactlyItsMaterialsLoss) {
  const PropagationModel with_slab = model_of(storeys(1), kUpstairsAp, PathLossModel::kItuWalls);
  const PropagationModel without = model_of(WallMesh{}, kUpstairsAp, PathLossModel::kItuWalls);
  const RadioLink link = with_slab.link(0, kDownstairs);
  EXPECT_EQ(link.slabs_crossed, 1);
  EXPECT_EQ(link.wall_count(), 0.0);
  EXPECT_FALSE(link.line_of_sight());
  for (const Bssid& b : with_slab.access_points()[0].bssids) {
    const double drop =
        without.mean_rssi_dbm(0, b, kDownstairs) - with_slab.mean_rssi_dbm(0, b, kDownstairs);
    EXPECT_NEAR(drop, tr38901_concrete_db(b.frequency_mhz()), 1e-9) << b.frequency_mhz();
  }
}

TEST(FloorSlab, UnderItuSiteGeneralAFloorCostsP1238sFloorPenetrationFactor) {
  const auto kind = PathLossModel::kItuSiteGeneral;
  const PropagationModel with_slab = model_of(storeys(1), kUpstairsAp, kind);
  const PropagationModel without = model_of(WallMesh{}, kUpstairsAp, kind);
  for (const Bssid& b : with_slab.access_points()[0].bssids) {
    const double drop =
        without.mean_rssi_dbm(0, b, kDownstairs) - with_slab.mean_rssi_dbm(0, b, kDownstairs);
    EXPECT_NEAR(drop, p1238_office_one_floor_db(b.frequency_mhz()), 1e-9) << b.frequency_mhz();
  }
  // Two floors down: the one-floor factor and 4 dB for the second (the 1.8-2 GHz row's step).
  const Eigen::Vector3d two_up(0.0, 0.0, 8.9);
  const PropagationModel two_slabs = model_of(storeys(2), two_up, kind);
  const PropagationModel none = model_of(WallMesh{}, two_up, kind);
  EXPECT_EQ(two_slabs.link(0, kDownstairs).slabs_crossed, 2);
  for (const Bssid& b : two_slabs.access_points()[0].bssids) {
    const double drop =
        none.mean_rssi_dbm(0, b, kDownstairs) - two_slabs.mean_rssi_dbm(0, b, kDownstairs);
    EXPECT_NEAR(drop, p1238_office_one_floor_db(b.frequency_mhz()) + 4.0, 1e-9);
  }
}

TEST(FloorSlab, ASlabIsCountedOncePerFloorAndNotOnTheSameStorey) {
  const PropagationModel two = model_of(storeys(2), {0.0, 0.0, 8.9}, PathLossModel::kItuWalls);
  const RadioLink down_two = two.link(0, kDownstairs);
  EXPECT_EQ(down_two.slabs_crossed, 2);
  EXPECT_EQ(down_two.slabs_per_material[material_index(WallMaterial::kConcrete)], 2.0);
  // Receiver on the AP's storey: nothing between them.
  const RadioLink same = two.link(0, {6.0, 2.0, 7.6});
  EXPECT_EQ(same.slabs_crossed, 0);
  EXPECT_TRUE(same.line_of_sight());
  // Walls and slabs stay apart: a brick wall on the lower storey (the segment meets it at
  // x = 5, z = 1.95 m) adds a wall, not a floor.
  WallMesh mesh = storeys(1);
  test::add_wall_x(mesh, 5.0f, 0.15f, 10.0f, kSlabBottomM, WallMaterial::kBrick, 1);
  const RadioLink both = model_of(mesh, kUpstairsAp, PathLossModel::kItuWalls).link(0, kDownstairs);
  EXPECT_EQ(both.slabs_crossed, 1);
  EXPECT_EQ(both.wall_count(), 1.0);
  EXPECT_EQ(both.walls_per_material[material_index(WallMaterial::kBrick)], 1.0);
  // itu_site_general counts the floor but not the wall.
  const RadioLink general =
      model_of(mesh, kUpstairsAp, PathLossModel::kItuSiteGeneral).link(0, kDownstairs);
  EXPECT_EQ(general.slabs_crossed, 1);
  EXPECT_EQ(general.wall_count(), 0.0);
}

TEST(FloorSlab, ARadioMapOfTheLowerStoreyHearsTheApUpstairsThroughTheSlab) {
  const PropagationModel with_slab = model_of(storeys(1), kUpstairsAp, PathLossModel::kItuWalls);
  const PropagationModel without = model_of(WallMesh{}, kUpstairsAp, PathLossModel::kItuWalls);
  RadioMapArea lower;
  lower.bounds_min_m = {-10, -10};
  lower.bounds_max_m = {10, 10};
  lower.ceiling_m = kSlabBottomM;
  RadioMapOptions options;
  options.resolution_m = 2.0;
  options.receiver_height_m = 1.2;
  options.threads = 1;
  const RadioMap map = compute_radio_map(with_slab, lower, options);
  ASSERT_EQ(map.cols * map.rows, 100);
  for (int r = 0; r < map.rows; ++r) {
    for (int c = 0; c < map.cols; ++c) {
      const Eigen::Vector2d xy = map.cell_center_m(c, r);
      const Eigen::Vector3d rx(xy.x(), xy.y(), 1.2);
      // The stronger radio, each weakened by its own band's concrete loss.
      double expected = -1e9;
      for (const Bssid& b : without.access_points()[0].bssids)
        expected = std::max(
            expected, without.mean_rssi_dbm(0, b, rx) - tr38901_concrete_db(b.frequency_mhz()));
      EXPECT_NEAR(map.at(c, r), expected, 1e-4) << c << "," << r;
      EXPECT_GT(map.at(c, r), -92.0);  // heard: above a typical sensitivity
    }
  }
}

}  // namespace
}  // namespace wifislam::radio_model
