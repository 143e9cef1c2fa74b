// compute_radio_map on an area handed to it, as any caller of the radio model would hand one: its
// bounds set the grid, its ceiling bounds the receiver height, and its mask says which cells are
// computed. The simulator's plan-based area is tested in tests/sim/site.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "radio_model/radio_map.hpp"
#include "tests/radio_model/test_walls.hpp"

namespace wifislam::radio_model {
namespace {

// One AP at x = 2 and a brick wall at x = 5, over the rectangle (0, -4)-(10, 4). The model copies
// the walls into Embree: the mesh need not outlive it.
PropagationModel one_ap_behind_a_wall() {
  WallMesh walls;
  test::add_wall_x(walls, 5.0f, 0.15f, 10.0f, 3.0f, WallMaterial::kBrick, 0);
  MacAllocator macs(5);
  std::vector<AccessPoint> aps{make_access_point(0, {2, 0, 2.5}, 20, 1, 5, macs)};
  PropagationOptions options;
  options.shadowing_sigma_db = 0.0;
  return PropagationModel(walls, {0, -4}, {10, 4}, std::move(aps), options, 5);
}

RadioMapArea the_models_rectangle() {
  RadioMapArea area;
  area.bounds_min_m = {0, -4};
  area.bounds_max_m = {10, 4};
  area.ceiling_m = 3.0;
  return area;
}

TEST(RadioMapArea, TheMaskSaysWhichCellsAreComputedAndEachIsTheModelAtItsCentre) {
  const PropagationModel model = one_ap_behind_a_wall();
  RadioMapArea area = the_models_rectangle();
  // Compute only the row through y in [0, 1): every other cell stays NaN.
  int calls = 0;
  area.cells_to_compute = [&calls](const RadioMap& grid) {
    ++calls;
    std::vector<bool> mask(static_cast<std::size_t>(grid.cols) * grid.rows, false);
    for (int c = 0; c < grid.cols; ++c) {
      const int r = static_cast<int>(std::floor((0.5 - grid.origin_m.y()) / grid.resolution_m));
      mask[static_cast<std::size_t>(r) * grid.cols + c] = true;
    }
    return mask;
  };
  RadioMapOptions options;
  options.resolution_m = 1.0;
  options.receiver_height_m = 1.0;
  options.threads = 1;
  const RadioMap map = compute_radio_map(model, area, options);
  EXPECT_EQ(calls, 1);
  ASSERT_EQ(map.cols, 10);
  ASSERT_EQ(map.rows, 8);
  int computed = 0;
  for (int r = 0; r < map.rows; ++r)
    for (int c = 0; c < map.cols; ++c) computed += std::isfinite(map.at(c, r));
  EXPECT_EQ(computed, 10);
  // Each computed cell is the model's mean RSSI at its centre (the AP's stronger radio); the cell
  // at x = 6.5 is beyond the wall at x = 5, the one at x = 3.5 on the AP's side.
  const auto expected = [&](double x) {
    const Eigen::Vector3d rx(x, 0.5, 1.0);
    double best = -1e9;
    for (const Bssid& b : model.access_points()[0].bssids)
      best = std::max(best, model.mean_rssi_dbm(0, b, rx));
    return static_cast<float>(best);
  };
  const float near = map.at(3, 4), far = map.at(6, 4);
  EXPECT_EQ(near, expected(3.5));
  EXPECT_EQ(far, expected(6.5));
  EXPECT_EQ(model.link(0, {3.5, 0.5, 1.0}).wall_count(), 0.0);
  EXPECT_EQ(model.link(0, {6.5, 0.5, 1.0}).wall_count(), 1.0);

  // Without a mask (or with free_space_only off) every cell is computed.
  options.free_space_only = false;
  const RadioMap all = compute_radio_map(model, area, options);
  for (float v : all.rssi_dbm) EXPECT_TRUE(std::isfinite(v));
  EXPECT_EQ(all.at(3, 4), near);
}

TEST(RadioMapArea, RejectsAReceiverAboveTheCeilingAndAMaskOfTheWrongSize) {
  const PropagationModel model = one_ap_behind_a_wall();
  RadioMapArea area = the_models_rectangle();
  RadioMapOptions options;
  options.resolution_m = 1.0;
  options.receiver_height_m = 3.5;
  EXPECT_THROW(compute_radio_map(model, area, options), InvalidInputError);
  options.receiver_height_m = 1.0;
  area.cells_to_compute = [](const RadioMap&) { return std::vector<bool>(3, true); };
  EXPECT_THROW(compute_radio_map(model, area, options), InvalidInputError);
}

}  // namespace
}  // namespace wifislam::radio_model
