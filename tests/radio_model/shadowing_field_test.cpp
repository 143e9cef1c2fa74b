#include "radio_model/shadowing_field.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

namespace wifislam::radio_model {
namespace {

// Sample correlation of the field at lag `lag_m` over a grid of spots, pooled over fields drawn
// from `fields` seeds (one site, as the propagation model draws one field per AP).
struct FieldStatistics {
  double rms_db = 0.0;
  double correlation = 0.0;
};

FieldStatistics statistics_at_lag(const ShadowingGrid& grid, int fields,
                                  const Eigen::Vector2d& lag_m, double extent_m) {
  double s2 = 0.0, cross = 0.0, s2_lagged = 0.0;
  int n = 0;
  for (int f = 0; f < fields; ++f) {
    const ShadowingField field = grid.draw(Rng::stream(f, "shadowing test"));
    // Spots 7.3 m apart (about 2.4 decorrelation distances: nearly independent samples), at
    // fractional cell offsets so that interpolated points are tested, not only nodes.
    for (double y = 1.1; y + lag_m.y() < extent_m - 1; y += 7.3) {
      for (double x = 1.3; x + lag_m.x() < extent_m - 1; x += 7.3) {
        const double a = field.at_db({x, y}), b = field.at_db(Eigen::Vector2d(x, y) + lag_m);
        s2 += a * a;
        s2_lagged += b * b;
        cross += a * b;
        ++n;
      }
    }
  }
  return {std::sqrt(s2 / n), cross / std::sqrt(s2 * s2_lagged)};
}

// Gudmundson's exp(-d / L) at four lags, along both axes and on a diagonal, and sigma everywhere:
// the issue measured the separable field at 0.15 on the 4.24 m diagonal against 0.24 and an rms
// of 3.74 dB for a 4 dB setting. Spots are off the grid nodes, where the variance-normalised
// blend reads correlations about 0.03 high (shadowing_field.hpp); 16 fields of 120 m x 120 m
// give about 4000 nearly independent spot pairs per lag, a standard error of the correlation of
// about 0.015 and of the rms of about 1 %.
TEST(ShadowingField, IsIsotropicWithGudmundsonCorrelationAndTheRequestedSigma) {
  const double sigma = 4.0, L = 3.0, extent = 120.0;
  const ShadowingGrid grid({0, 0}, {extent, extent}, sigma, L);
  EXPECT_EQ(grid.cell_m(), 0.25);
  EXPECT_LT(grid.negative_mass(), 1e-6);
  const int fields = 16;
  const double diagonal = std::sqrt(0.5);
  for (const double d : {1.5, 3.0, 4.24, 6.0}) {
    const FieldStatistics along_x = statistics_at_lag(grid, fields, {d, 0.0}, extent);
    const FieldStatistics along_y = statistics_at_lag(grid, fields, {0.0, d}, extent);
    const FieldStatistics on_diagonal =
        statistics_at_lag(grid, fields, {d * diagonal, d * diagonal}, extent);
    const double expected = std::exp(-d / L);
    EXPECT_NEAR(along_x.correlation, expected, 0.06) << "lag " << d << " m along x";
    EXPECT_NEAR(along_y.correlation, expected, 0.06) << "lag " << d << " m along y";
    EXPECT_NEAR(on_diagonal.correlation, expected, 0.06) << "lag " << d << " m on a diagonal";
    // Isotropy: the same distance along an axis and on a diagonal correlates alike.
    EXPECT_NEAR(on_diagonal.correlation, 0.5 * (along_x.correlation + along_y.correlation), 0.05)
        << "lag " << d << " m";
    EXPECT_NEAR(along_x.rms_db, sigma, 0.15);
    std::printf("lag %.2f m: corr x %.3f y %.3f diagonal %.3f, exp(-d/L) %.3f; rms %.2f dB\n", d,
                along_x.correlation, along_y.correlation, on_diagonal.correlation, expected,
                along_x.rms_db);
  }
}

TEST(ShadowingField, IsDeterministicPerStreamAndZeroWhenDisabled) {
  const ShadowingGrid grid({0, 0}, {60, 40}, 4.0, 3.0);
  const ShadowingField a = grid.draw(Rng::stream(9, "test"));
  const ShadowingField b = ShadowingField({0, 0}, {60, 40}, 4.0, 3.0, Rng::stream(9, "test"));
  const ShadowingField c = grid.draw(Rng::stream(10, "test"));
  int differ = 0;
  for (double x = 0.3; x < 60; x += 2.9) {
    EXPECT_EQ(a.at_db({x, 17.7}), b.at_db({x, 17.7}));
    differ += std::abs(a.at_db({x, 17.7}) - c.at_db({x, 17.7})) > 0.1;
  }
  EXPECT_GT(differ, 15);
  EXPECT_EQ(ShadowingField({0, 0}, {10, 10}, 0.0, 3.0, Rng::stream(9, "test")).at_db({1, 1}), 0.0);
}

// A site at the scene limit (20 km across) once asked for 1.6e9 cells per access point. The grid
// is capped: memory and time stay bounded, and every point keeps the requested sigma (the
// variance-normalised blend) although nodes ~40 m apart are independent.
TEST(ShadowingField, SitesTwentyKilometresAcrossStayWithinTheCellCap) {
  const auto start = std::chrono::steady_clock::now();
  const ShadowingGrid grid({-10000, -10000}, {10000, 10000}, 4.0, 3.0);
  const ShadowingField field = grid.draw(Rng::stream(9, "test"));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 5.0);
  const double cells = std::pow(20004.0 / field.cell_m() + 2, 2);
  EXPECT_LE(cells, static_cast<double>(ShadowingField::kMaxCells));
  EXPECT_GT(field.cell_m(), 30.0);
  double s2 = 0;
  int n = 0;
  for (double y = -9000; y < 9000; y += 97.0) {
    for (double x = -9000; x < 9000; x += 89.0) {
      const double v = field.at_db({x, y});
      s2 += v * v;
      ++n;
    }
  }
  EXPECT_NEAR(std::sqrt(s2 / n), 4.0, 0.2);
}

}  // namespace
}  // namespace wifislam::radio_model
