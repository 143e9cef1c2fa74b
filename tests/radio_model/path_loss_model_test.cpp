// The three path loss models of propagation_model.hpp (radio.model), each against its formula
// written out here from the recommendation, on one hand-built wall.
#include <gtest/gtest.h>

#include <cmath>

#include "radio_model/access_point.hpp"
#include "radio_model/itu_p1238.hpp"
#include "radio_model/propagation_model.hpp"
#include "tests/radio_model/test_walls.hpp"

namespace wifislam::radio_model {
namespace {

TEST(ItuP1238Fit, OfficeRowsMatchHandComputedValues) {
  // 10 alpha log10(d) + beta + 10 gamma log10(f_GHz), P.1238-11 Table 2, computed by hand.
  EXPECT_NEAR(itu_p1238_fit_loss_db(itu_p1238_office_fit(true), 2437, 10), 57.0732, 1e-3);
  EXPECT_NEAR(itu_p1238_fit_loss_db(itu_p1238_office_fit(false), 5180, 10), 71.1310, 1e-3);
  // Below the row's shortest distance (2 m LoS, 4 m NLoS) the loss stays at its value there.
  EXPECT_NEAR(itu_p1238_fit_loss_db(itu_p1238_office_fit(true), 2412, 0.5), 46.7773, 1e-3);
  EXPECT_EQ(itu_p1238_fit_loss_db(itu_p1238_office_fit(false), 2412, 1.0),
            itu_p1238_fit_loss_db(itu_p1238_office_fit(false), 2412, 4.0));
  // A wall can only lower RSSI: NLoS loses more than LoS at every distance in the Wi-Fi bands.
  for (double f : {2412.0, 2484.0, 5180.0, 5885.0}) {
    for (double d = 0.5; d < 200.0; d *= 1.1) {
      EXPECT_GT(itu_p1238_fit_loss_db(itu_p1238_office_fit(false), f, d),
                itu_p1238_fit_loss_db(itu_p1238_office_fit(true), f, d))
          << f << " MHz, " << d << " m";
    }
  }
}

struct Link {
  double rssi_24_dbm, rssi_5_dbm;
  double f_24_mhz, f_5_mhz;
};

// One AP at the origin, a receiver 12 m away behind one brick wall at x = 6 (or no wall).
Link link_behind_wall(PropagationOptions options, bool wall) {
  WallMesh mesh;
  if (wall) test::add_wall_x(mesh, 6.0f, 0.15f, 10.0f, 2.8f, WallMaterial::kBrick, 1);
  MacAllocator macs(5);
  const Eigen::Vector3d ap(0, 0, 2.0), rx(12, 0, 2.0);
  PropagationModel model(mesh, {-20, -20}, {20, 20}, {make_access_point(0, ap, 20.0, 1, 5, macs)},
                         options, 5);
  const AccessPoint& a = model.access_points()[0];
  return {model.mean_rssi_dbm(0, a.bssids.front(), rx), model.mean_rssi_dbm(0, a.bssids.back(), rx),
          a.bssids.front().frequency_mhz(), a.bssids.back().frequency_mhz()};
}

PropagationOptions without_shadowing(PathLossModel model) {
  PropagationOptions o;
  o.model = model;
  o.shadowing_sigma_db = 0.0;
  return o;
}

TEST(PathLossModels, ItuWallsIsTheDistanceLawWithNTwentyTwoPlusTheWall) {
  const auto o = without_shadowing(PathLossModel::kItuWalls);
  const Link open = link_behind_wall(o, false), walled = link_behind_wall(o, true);
  const double d = 12.0;
  EXPECT_NEAR(open.rssi_24_dbm, 20 - (20 * std::log10(open.f_24_mhz) + 22 * std::log10(d) - 28),
              1e-9);
  // Brick: COST 231's 6.9 dB at 1.8 GHz plus the absorption of 0.15 m of P.2040 brick, the
  // default wall thickness (wall_materials.hpp).
  for (double f_mhz : {open.f_24_mhz, open.f_5_mhz}) {
    const double expected = 6.9 + p2040_absorption_db(kP2040Brick, 0.15, f_mhz) -
                            p2040_absorption_db(kP2040Brick, 0.15, 1800.0);
    const double measured = f_mhz == open.f_24_mhz ? open.rssi_24_dbm - walled.rssi_24_dbm
                                                   : open.rssi_5_dbm - walled.rssi_5_dbm;
    EXPECT_NEAR(measured, expected, 1e-9) << f_mhz;
  }
}

TEST(PathLossModels, ItuSiteGeneralTakesNFromTheTablePerBandAndIgnoresWalls) {
  for (auto [environment, n24, n5] : {std::tuple{RadioEnvironment::kOffice, 30.0, 31.0},
                                      std::tuple{RadioEnvironment::kResidential, 28.0, 30.0},
                                      std::tuple{RadioEnvironment::kCommercial, 22.0, 22.0}}) {
    auto o = without_shadowing(PathLossModel::kItuSiteGeneral);
    o.environment = environment;
    const Link open = link_behind_wall(o, false), walled = link_behind_wall(o, true);
    const double d = 12.0;
    EXPECT_NEAR(open.rssi_24_dbm, 20 - (20 * std::log10(open.f_24_mhz) + n24 * std::log10(d) - 28),
                1e-9)
        << to_string(environment);
    EXPECT_NEAR(open.rssi_5_dbm, 20 - (20 * std::log10(open.f_5_mhz) + n5 * std::log10(d) - 28),
                1e-9)
        << to_string(environment);
    EXPECT_EQ(open.rssi_24_dbm, walled.rssi_24_dbm);
    EXPECT_EQ(open.rssi_5_dbm, walled.rssi_5_dbm);
  }
}

TEST(PathLossModels, ItuSiteGeneralFitIsLosWithoutAWallAndNlosBehindOne) {
  const auto o = without_shadowing(PathLossModel::kItuSiteGeneralFit);
  const Link open = link_behind_wall(o, false), walled = link_behind_wall(o, true);
  const double d = 12.0;
  auto fit = [&](double alpha, double beta, double gamma, double f_mhz) {
    return 20 - (10 * alpha * std::log10(d) + beta + 10 * gamma * std::log10(f_mhz * 1e-3));
  };
  EXPECT_NEAR(open.rssi_24_dbm, fit(1.46, 34.62, 2.03, open.f_24_mhz), 1e-9);
  EXPECT_NEAR(walled.rssi_24_dbm, fit(2.46, 29.53, 2.38, open.f_24_mhz), 1e-9);
  EXPECT_NEAR(walled.rssi_5_dbm, fit(2.46, 29.53, 2.38, open.f_5_mhz), 1e-9);
}

TEST(PathLossModels, ShadowingSigmaIsTheModelsUnlessTheSceneSetsIt) {
  PropagationOptions o;
  EXPECT_EQ(o.shadowing_sigma_db_for(RadioBand::k2_4GHz, true), 4.0);  // itu_walls
  o.model = PathLossModel::kItuSiteGeneral;
  EXPECT_EQ(o.shadowing_sigma_db_for(RadioBand::k2_4GHz, false), 10.0);  // P.1238-7 Table 4
  EXPECT_EQ(o.shadowing_sigma_db_for(RadioBand::k5GHz, false), 12.0);
  o.model = PathLossModel::kItuSiteGeneralFit;
  EXPECT_EQ(o.shadowing_sigma_db_for(RadioBand::k5GHz, true), 3.76);  // P.1238-11 Table 2
  EXPECT_EQ(o.shadowing_sigma_db_for(RadioBand::k5GHz, false), 5.04);
  o.shadowing_sigma_db = 6.0;
  EXPECT_EQ(o.shadowing_sigma_db_for(RadioBand::k5GHz, false), 6.0);

  // One field per AP scaled per band: under the site-general model the 5 GHz radio's shadowing
  // is 12 / 10 of the 2.4 GHz radio's at every spot.
  PropagationOptions site_general;
  site_general.model = PathLossModel::kItuSiteGeneral;
  MacAllocator macs(9);
  PropagationModel model(WallMesh{}, {-20, -20}, {20, 20},
                         {make_access_point(0, {0, 0, 2}, 20.0, 1, 9, macs)}, site_general, 9);
  int nonzero = 0;
  for (double x = -15; x < 15; x += 1.7) {
    const RadioLink link = model.link(0, {x, 3.0, 1.0});
    EXPECT_NEAR(model.shadowing_db(link, RadioBand::k5GHz),
                1.2 * model.shadowing_db(link, RadioBand::k2_4GHz), 1e-9);
    nonzero += std::abs(link.shadowing_normal) > 0.05;
  }
  EXPECT_GT(nonzero, 10);
}

}  // namespace
}  // namespace wifislam::radio_model
