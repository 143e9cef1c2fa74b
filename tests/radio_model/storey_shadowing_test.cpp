// Shadowing in 3-D: one field per access point and storey, mixed so that the same (x, y) on two
// storeys dz apart correlates as exp(-dz / decorrelation) (propagation_model.hpp). The lowest
// storey keeps the field a one-storey building has always had.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "radio_model/propagation_model.hpp"

namespace wifislam::radio_model {
namespace {

std::vector<AccessPoint> aps(int count) {
  MacAllocator macs(21);
  std::vector<AccessPoint> out;
  for (int i = 0; i < count; ++i)
    out.push_back(make_access_point(i, {1.0 * i, 0.0, 2.5}, 20.0, 1, 21, macs));
  return out;
}

PropagationModel model_with_storeys(std::vector<double> elevations_m, int ap_count) {
  PropagationOptions options;  // itu_walls: sigma 4 dB, decorrelation 3 m
  options.storey_elevations_m = std::move(elevations_m);
  return PropagationModel(WallMesh{}, {0, 0}, {40, 40}, aps(ap_count), options, 21);
}

TEST(StoreyShadowing, TheLowestStoreyIsTheOneStoreyField) {
  const PropagationModel one = model_with_storeys({}, 3);
  const PropagationModel two = model_with_storeys({0.0, 3.2}, 3);
  for (std::size_t a = 0; a < 3; ++a) {
    for (double x : {2.0, 17.5, 33.0}) {
      const Eigen::Vector3d p(x, 0.6 * x, 1.2);
      EXPECT_EQ(two.shadowing_normal(a, p), one.shadowing_normal(a, p));
      EXPECT_EQ(two.link(a, p).shadowing_normal, one.link(a, p).shadowing_normal);
    }
  }
}

TEST(StoreyShadowing, TwoStoreysCorrelateAsExpOfTheirSeparationOverTheDecorrelationDistance) {
  const double storey_m = 3.2, decorrelation_m = 3.0;
  const PropagationModel model = model_with_storeys({0.0, storey_m}, 40);
  // The same (x, y) on both storeys, on a 5 m lattice (neighbours nearly independent).
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  int n = 0;
  for (std::size_t a = 0; a < 40; ++a) {
    for (double x = 2.5; x < 40.0; x += 5.0) {
      for (double y = 2.5; y < 40.0; y += 5.0) {
        const double lower = model.shadowing_normal(a, {x, y, 1.2});
        const double upper = model.shadowing_normal(a, {x, y, storey_m + 1.2});
        sxy += lower * upper;
        sxx += lower * lower;
        syy += upper * upper;
        ++n;
      }
    }
  }
  const double correlation = sxy / std::sqrt(sxx * syy);
  EXPECT_NEAR(correlation, std::exp(-storey_m / decorrelation_m), 0.08) << n << " pairs";
  // Both storeys' fields have unit variance (the mix keeps it).
  EXPECT_NEAR(syy / n, sxx / n, 0.15);
  EXPECT_NEAR(syy / n, 1.0, 0.2);
}

TEST(StoreyShadowing, ElevationsThatDoNotRiseAreRefused) {
  EXPECT_THROW(model_with_storeys({0.0, 3.0, 3.0}, 1), InvalidInputError);
  EXPECT_THROW(model_with_storeys({3.0, 0.0}, 1), InvalidInputError);
}

}  // namespace
}  // namespace wifislam::radio_model
