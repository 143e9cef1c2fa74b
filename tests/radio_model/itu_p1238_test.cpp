#include "radio_model/itu_p1238.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace wifislam::radio_model {
namespace {

TEST(ItuP1238, PathLossMatchesHandComputedValues) {
  // 20 log10(f) + N log10(d) + Lf - 28, evaluated by hand (4 decimals).
  struct Case {
    double f_mhz, d_m, n, lf_db, expected_db;
  };
  const Case cases[] = {
      {2437, 10, 30, 0, 69.7371},   // office N, 2.4 GHz channel 6, 10 m
      {2412, 1, 28, 0, 39.6475},    // residential N, 1 m: only the frequency term
      {5180, 25, 31, 0, 89.6227},   // office N at 5.2 GHz, channel 36
      {2462, 40, 22, 0, 75.0711},   // commercial N, channel 11, 40 m
      {5745, 7.5, 30, 0, 73.4376},  // residential 5.2 GHz N (apartment), channel 149
      {2437, 15, 30, 15, 90.0198},  // office, one floor between: Lf = 15
      {5200, 3, 22, 6, 62.8167},    // commercial, one floor: Lf = 6
  };
  for (const Case& c : cases) {
    EXPECT_NEAR(itu_p1238_path_loss_db(c.f_mhz, c.d_m, c.n, c.lf_db), c.expected_db, 0.01)
        << "f=" << c.f_mhz << " d=" << c.d_m << " N=" << c.n;
  }
}

TEST(ItuP1238, TableCoefficientsFollowTheRecommendation) {
  EXPECT_EQ(itu_p1238_coefficients(RadioEnvironment::kResidential, RadioBand::k2_4GHz)
                .distance_coefficient,
            28.0);
  EXPECT_EQ(
      itu_p1238_coefficients(RadioEnvironment::kOffice, RadioBand::k2_4GHz).distance_coefficient,
      30.0);
  EXPECT_EQ(itu_p1238_coefficients(RadioEnvironment::kCommercial, RadioBand::k2_4GHz)
                .distance_coefficient,
            22.0);
  EXPECT_EQ(
      itu_p1238_coefficients(RadioEnvironment::kOffice, RadioBand::k5GHz).distance_coefficient,
      31.0);
  EXPECT_EQ(itu_p1238_coefficients(RadioEnvironment::kOffice, RadioBand::k2_4GHz).shadow_sigma_db,
            10.0);
  EXPECT_EQ(itu_p1238_coefficients(RadioEnvironment::kOffice, RadioBand::k5GHz).shadow_sigma_db,
            12.0);
  // Floor penetration (Table 3): residential 4n, office 15 + 4(n-1), commercial 6 + 3(n-1).
  // 1.8-2 GHz row.
  EXPECT_EQ(itu_p1238_floor_loss_db(RadioEnvironment::kOffice, 1900.0, 0), 0.0);
  EXPECT_EQ(itu_p1238_floor_loss_db(RadioEnvironment::kResidential, 1900.0, 2), 8.0);
  EXPECT_EQ(itu_p1238_floor_loss_db(RadioEnvironment::kOffice, 1900.0, 3), 23.0);
  EXPECT_EQ(itu_p1238_floor_loss_db(RadioEnvironment::kCommercial, 1900.0, 2), 9.0);
  // 2.4 and 5.2 GHz rows (P.1238-7 Table 3): office 14 and 16 dB, residential (apartment) 10 and
  // 13 dB for one floor; each further floor the 1.8-2 GHz row's 4 dB; commercial keeps that row.
  EXPECT_EQ(itu_p1238_floor_loss_db(RadioEnvironment::kOffice, 2437.0, 0), 0.0);
  EXPECT_EQ(itu_p1238_floor_loss_db(RadioEnvironment::kOffice, 2437.0, 1), 14.0);
  EXPECT_EQ(itu_p1238_floor_loss_db(RadioEnvironment::kOffice, 5180.0, 1), 16.0);
  EXPECT_EQ(itu_p1238_floor_loss_db(RadioEnvironment::kOffice, 5805.0, 2), 20.0);
  EXPECT_EQ(itu_p1238_floor_loss_db(RadioEnvironment::kResidential, 2412.0, 1), 10.0);
  EXPECT_EQ(itu_p1238_floor_loss_db(RadioEnvironment::kResidential, 5240.0, 3), 21.0);
  EXPECT_EQ(itu_p1238_floor_loss_db(RadioEnvironment::kCommercial, 2462.0, 2), 9.0);
}

TEST(ItuP1238, LossGrowsWithDistanceAndNeverBelowOneMetre) {
  double previous = itu_p1238_path_loss_db(2437, 1.0, kDefaultDistanceCoefficient, 0);
  EXPECT_EQ(itu_p1238_path_loss_db(2437, 0.2, kDefaultDistanceCoefficient, 0), previous);
  for (double d = 1.5; d < 80.0; d += 0.5) {
    const double loss = itu_p1238_path_loss_db(2437, d, kDefaultDistanceCoefficient, 0);
    EXPECT_GT(loss, previous) << d;
    previous = loss;
  }
}

TEST(ItuP1238, FiveGigahertzLosesMoreThanTwoPointFour) {
  for (double d : {2.0, 10.0, 30.0}) {
    EXPECT_NEAR(itu_p1238_path_loss_db(5180, d, 22, 0) - itu_p1238_path_loss_db(2412, d, 22, 0),
                20 * std::log10(5180.0 / 2412.0), 1e-9);
  }
}

TEST(RadioBand, ChannelFrequencies) {
  EXPECT_EQ(channel_frequency_khz(RadioBand::k2_4GHz, 1), 2412000);
  EXPECT_EQ(channel_frequency_khz(RadioBand::k2_4GHz, 11), 2462000);
  EXPECT_EQ(channel_frequency_khz(RadioBand::k5GHz, 36), 5180000);
  EXPECT_EQ(channel_frequency_khz(RadioBand::k5GHz, 165), 5825000);
}

}  // namespace
}  // namespace wifislam::radio_model
