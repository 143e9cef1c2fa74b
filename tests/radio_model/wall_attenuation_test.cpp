// Walls found by real Embree rays change RSSI by exactly their material's loss.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "radio_model/access_point.hpp"
#include "radio_model/embree_wall_scene.hpp"
#include "radio_model/propagation_model.hpp"
#include "tests/radio_model/test_walls.hpp"

namespace wifislam::radio_model {
namespace {

using test::add_two_face_wall_x;
using test::add_wall_x;

constexpr WallMaterial kMaterials[] = {WallMaterial::kPlasterboard, WallMaterial::kBrick,
                                       WallMaterial::kConcrete, WallMaterial::kGlass,
                                       WallMaterial::kWoodDoor};

PropagationOptions noise_free() {
  PropagationOptions o;
  o.shadowing_sigma_db = 0.0;
  o.fast_fading_sigma_db = 0.0;
  return o;
}

std::vector<AccessPoint> one_ap(const Eigen::Vector3d& at) {
  MacAllocator macs(7);
  return {make_access_point(0, at, 20.0, 2, 7, macs)};
}

struct Rssi {
  double ghz24, ghz5;
};

Rssi rssi_at(const WallMesh& mesh, const Eigen::Vector3d& ap, const Eigen::Vector3d& rx) {
  PropagationModel model(mesh, {-30, -30}, {30, 30}, one_ap(ap), noise_free(), 1);
  const AccessPoint& a = model.access_points()[0];
  return {model.mean_rssi_dbm(0, a.bssids.front(), rx),
          model.mean_rssi_dbm(0, a.bssids.back(), rx)};
}

TEST(WallAttenuation, ReceiverBehindKParallelWallsLosesExactlyKTimesTheWallLoss) {
  const Eigen::Vector3d ap(0, 0, 1.5), rx(20, 0.7, 1.0);
  const Rssi open = rssi_at(WallMesh{}, ap, rx);
  const WallLossTable table;
  const AccessPoint reference = one_ap(ap)[0];
  const double f24 = reference.bssids.front().frequency_mhz();
  const double f5 = reference.bssids.back().frequency_mhz();
  for (WallMaterial m : kMaterials) {
    for (int k = 1; k <= 4; ++k) {
      WallMesh mesh;
      for (int w = 0; w < k; ++w) add_wall_x(mesh, 3.0f + 4.0f * w, 0.15f, 10.0f, 2.8f, m, 100 + w);
      const Rssi behind = rssi_at(mesh, ap, rx);
      EXPECT_NEAR(open.ghz24 - behind.ghz24, k * table.loss_db(m, f24), 1e-9) << to_string(m) << k;
      EXPECT_NEAR(open.ghz5 - behind.ghz5, k * table.loss_db(m, f5), 1e-9) << to_string(m) << k;
      EXPECT_GT(open.ghz24 - behind.ghz24, 1.0);  // walls do change RSSI
    }
  }
}

TEST(WallAttenuation, DefaultWallLossesMatchTheCitedFigures) {
  const WallLossTable t(0.15);
  EXPECT_NEAR(t.loss_db(WallMaterial::kConcrete, 2400), 14.6, 1e-9);  // TR 38.901: 5 + 4 f
  EXPECT_NEAR(t.loss_db(WallMaterial::kConcrete, 5200), 25.8, 1e-9);
  EXPECT_NEAR(t.loss_db(WallMaterial::kGlass, 2400), 2.48, 1e-9);      // 2 + 0.2 f
  EXPECT_NEAR(t.loss_db(WallMaterial::kWoodDoor, 5200), 5.474, 1e-9);  // 4.85 + 0.12 f
  // COST 231 at 1.8 GHz plus P.2040-3 absorption, computed by hand from wall_materials.hpp.
  EXPECT_NEAR(t.loss_db(WallMaterial::kBrick, 1800), 6.9, 1e-9);     // heavy wall
  EXPECT_NEAR(t.loss_db(WallMaterial::kBrick, 2437), 7.0619, 1e-3);  // 0.15 m
  EXPECT_NEAR(t.loss_db(WallMaterial::kBrick, 5200), 7.5020, 1e-3);
  EXPECT_NEAR(WallLossTable(0.2).loss_db(WallMaterial::kBrick, 5200), 7.7026, 1e-3);
  EXPECT_NEAR(t.loss_db(WallMaterial::kPlasterboard, 1800), 3.4, 1e-9);     // light wall
  EXPECT_NEAR(t.loss_db(WallMaterial::kPlasterboard, 2437), 3.5204, 1e-3);  // 2 x 12.5 mm
  EXPECT_NEAR(t.loss_db(WallMaterial::kPlasterboard, 5200), 4.0248, 1e-3);
  for (WallMaterial m : kMaterials) EXPECT_GT(t.loss_db(m, 5200), t.loss_db(m, 2400));
}

TEST(WallAttenuation, P2040SlabAgreesWithItsLimitsAndWithTr38901Concrete) {
  // A lossless slab half a wavelength thick (inside it) is transparent: Fabry-Perot resonance.
  const P2040Material lossless{4.0, 0.0, 0.0, 0.0};
  const double f_mhz = 2400.0, lambda_in_m = 299792458.0 / (f_mhz * 1e6) / 2.0;
  EXPECT_NEAR(p2040_slab_loss_db(lossless, lambda_in_m / 2.0, f_mhz), 0.0, 1e-9);
  // A quarter wave reflects most: |T|^2 = 1 - ((n^2 - 1) / (n^2 + 1))^2 with n^2 = 4.
  EXPECT_NEAR(p2040_slab_loss_db(lossless, lambda_in_m / 4.0, f_mhz),
              -10 * std::log10(1 - std::pow(3.0 / 5.0, 2)), 1e-9);
  // A thick lossy slab: its absorption plus two interface losses (the internal echoes die out).
  const double thick_m = 2.0;
  const std::complex<double> n =
      std::sqrt(std::complex<double>(5.24, -17.98 * 0.0462 * std::pow(2.4, 0.7822) / 2.4));
  const double k0 = 2 * M_PI * f_mhz * 1e6 / 299792458.0;
  const double interfaces_db = -20 * std::log10(std::abs(4.0 * n / ((1.0 + n) * (1.0 + n))));
  EXPECT_NEAR(p2040_absorption_db(kP2040Concrete, thick_m, f_mhz),
              20 * std::log10(std::exp(1.0)) * k0 * -n.imag() * thick_m, 1e-9);
  EXPECT_NEAR(p2040_slab_loss_db(kP2040Concrete, thick_m, f_mhz),
              p2040_absorption_db(kP2040Concrete, thick_m, f_mhz) + interfaces_db, 1e-6);
  // P.2040's concrete at 0.2 m is TR 38.901's concrete to within 1 dB: the two sources agree.
  for (double f : {2400.0, 5200.0, 5800.0}) {
    EXPECT_NEAR(p2040_slab_loss_db(kP2040Concrete, 0.2, f), 5.0 + 4.0 * f * 1e-3, 1.0) << f;
  }
}

TEST(WallAttenuation, DoorOpeningCrossesNoWall) {
  WallMesh mesh;
  add_wall_x(mesh, 5.0f, 0.15f, 10.0f, 2.8f, WallMaterial::kBrick, 1, /*door_width=*/0.9f);
  EmbreeWallScene scene(mesh);
  // Straight through the opening (below the lintel).
  EXPECT_TRUE(scene.walls_crossed({0, 0, 1.2}, {10, 0.1, 1.0}).empty());
  // Beside the opening: the wall counts once.
  const auto beside = scene.walls_crossed({0, 2, 1.2}, {10, 2, 1.0});
  ASSERT_EQ(beside.size(), 1u);
  EXPECT_EQ(beside[0].wall_id, 1);
  EXPECT_EQ(beside[0].material, WallMaterial::kBrick);
  EXPECT_NEAR(beside[0].distance_m, 5.0, 0.01);
  // Above the door: the lintel is the same wall.
  EXPECT_EQ(scene.walls_crossed({0, 0, 2.5}, {10, 0, 2.5}).size(), 1u);

  const Eigen::Vector3d ap(0, 0, 1.5);
  const Rssi open = rssi_at(WallMesh{}, ap, {10, 0.1, 1.0});
  const Rssi through_door = rssi_at(mesh, ap, {10, 0.1, 1.0});
  EXPECT_DOUBLE_EQ(open.ghz24, through_door.ghz24);
  EXPECT_DOUBLE_EQ(open.ghz5, through_door.ghz5);
}

TEST(WallAttenuation, ThickWallsAndTwoFacedWallsCountOnce) {
  WallMesh mesh;
  add_wall_x(mesh, 2.0f, 1.0f, 10.0f, 2.8f, WallMaterial::kConcrete, 5);         // 1 m thick box
  add_two_face_wall_x(mesh, 6.0f, 0.12f, 10.0f, 2.8f, WallMaterial::kGlass, 6);  // two faces
  EmbreeWallScene scene(mesh);
  const auto crossed = scene.walls_crossed({0, 0.3, 1.5}, {10, -0.4, 1.0});
  ASSERT_EQ(crossed.size(), 2u);
  EXPECT_EQ(crossed[0].wall_id, 5);
  EXPECT_EQ(crossed[0].material, WallMaterial::kConcrete);
  EXPECT_EQ(crossed[1].wall_id, 6);
  EXPECT_EQ(crossed[1].material, WallMaterial::kGlass);
  EXPECT_LT(crossed[0].distance_m, crossed[1].distance_m);
}

TEST(WallAttenuation, SegmentThroughASharedTriangleEdgeCountsTheWallOnce) {
  // The face quad at x = 2 is split along its diagonal from (2, -10, 0) to (2, 10, 2.8); at
  // y = 0 the diagonal is at z = 1.4, so this segment passes exactly through the shared edge.
  WallMesh mesh;
  add_two_face_wall_x(mesh, 2.0f, 0.1f, 10.0f, 2.8f, WallMaterial::kBrick, 9);
  EmbreeWallScene scene(mesh);
  const auto crossed = scene.walls_crossed({0, 0, 1.4}, {4, 0, 1.4});
  ASSERT_EQ(crossed.size(), 1u);
  EXPECT_EQ(crossed[0].wall_id, 9);
}

TEST(WallAttenuation, EndpointsOnAFaceAndShortSegmentsCrossNothing) {
  WallMesh mesh;
  add_wall_x(mesh, 2.0f, 0.15f, 10.0f, 2.8f, WallMaterial::kBrick, 3);
  EmbreeWallScene scene(mesh);
  EXPECT_TRUE(scene.walls_crossed({0, 0, 1}, {1.9, 0, 1}).empty());
  EXPECT_TRUE(scene.walls_crossed({1, 0, 1}, {1, 0, 1}).empty());
  EXPECT_EQ(scene.triangle_count(), 12u);
  EXPECT_NEAR(scene.first_hit_m({0, 0, 1}, {1, 0, 0}, 100.0), 2.0, 1e-5);
  EXPECT_LT(scene.first_hit_m({0, 0, 1}, {-1, 0, 0}, 100.0), 0.0);
}

TEST(Propagation, RssiFallsMonotonicallyWithDistanceWithoutWalls) {
  const Eigen::Vector3d ap(0, 0, 2.5);
  PropagationModel model(WallMesh{}, {-5, -5}, {60, 5}, one_ap(ap), noise_free(), 3);
  for (const Bssid& b : model.access_points()[0].bssids) {
    double previous = model.mean_rssi_dbm(0, b, Eigen::Vector3d(0.5, 0, 1.0));
    for (double x = 1.0; x < 60.0; x += 0.25) {
      const double v = model.mean_rssi_dbm(0, b, Eigen::Vector3d(x, 0, 1.0));
      EXPECT_LE(v, previous) << x;
      previous = v;
    }
  }
}

TEST(Propagation, FiveGigahertzLosesMoreThanTwoPointFourAtEqualDistanceAndWalls) {
  WallMesh mesh;
  add_wall_x(mesh, 3.0f, 0.15f, 10.0f, 2.8f, WallMaterial::kBrick, 1);
  add_wall_x(mesh, 7.0f, 0.15f, 10.0f, 2.8f, WallMaterial::kPlasterboard, 2);
  for (double x : {2.0, 5.0, 9.0, 15.0}) {
    const Rssi r = rssi_at(mesh, {0, 0, 2.5}, {x, 1.0, 1.0});
    EXPECT_GT(r.ghz24, r.ghz5) << x;
  }
}

}  // namespace
}  // namespace wifislam::radio_model
