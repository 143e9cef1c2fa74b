#include <gtest/gtest.h>

#include <cairo.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "radio_model/radio_map.hpp"
#include "sim/site/radio_map_over_plan.hpp"
#include "sim/world/plan_queries.hpp"
#include "tests/radio_model/test_walls.hpp"
#include "tests/sim/site/test_plan.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::radio_model {
namespace {

struct Fixture {
  sim::world::FloorPlan plan = test::corridor_with_rooms(5);
  WallMesh mesh;
  std::unique_ptr<PropagationModel> model;
  Fixture() {
    // Room walls along the corridor's north side (with doors), one wall_id per room front.
    for (int i = 0; i < 5; ++i) {
      WallMesh& m = mesh;
      using V = Eigen::Vector3f;
      test::add_box(m, V(4.0f * i, 2.0f, 0), V(4.0f * i + 1.5f, 2.15f, 2.8f), WallMaterial::kBrick,
                    i);
      test::add_box(m, V(4.0f * i + 2.4f, 2.0f, 0), V(4.0f * i + 4.0f, 2.15f, 2.8f),
                    WallMaterial::kBrick, i);
    }
    MacAllocator macs(3);
    std::vector<AccessPoint> aps;
    aps.push_back(make_access_point(0, {2, 4, 2.5}, 20, 2, 3, macs));
    aps.push_back(make_access_point(1, {18, 4, 2.5}, 20, 2, 3, macs));
    model = std::make_unique<PropagationModel>(mesh, plan.bounds_min_m, plan.bounds_max_m,
                                               std::move(aps), PropagationOptions{}, 3);
  }
};

TEST(RadioMap, StrongestIsTheMaxOverApsAndThreadCountDoesNotMatter) {
  Fixture f;
  RadioMapOptions o;
  o.resolution_m = 0.5;
  o.threads = 1;
  const RadioMap strongest1 = sim::site::compute_radio_map(*f.model, f.plan, o);
  o.threads = 2;
  const RadioMap strongest2 = sim::site::compute_radio_map(*f.model, f.plan, o);
  ASSERT_EQ(strongest1.rssi_dbm.size(), strongest2.rssi_dbm.size());
  EXPECT_EQ(std::memcmp(strongest1.rssi_dbm.data(), strongest2.rssi_dbm.data(),
                        strongest1.rssi_dbm.size() * sizeof(float)),
            0);
  EXPECT_EQ(strongest1.best_ap_id, strongest2.best_ap_id);
  EXPECT_EQ(strongest1.cols, 45);  // 22.4 m / 0.5
  EXPECT_EQ(strongest1.rows, 13);  // 6.4 m / 0.5

  o.ap_id = 0;
  const RadioMap ap0 = sim::site::compute_radio_map(*f.model, f.plan, o);
  o.ap_id = 1;
  const RadioMap ap1 = sim::site::compute_radio_map(*f.model, f.plan, o);
  int from0 = 0, from1 = 0;
  for (std::size_t i = 0; i < ap0.rssi_dbm.size(); ++i) {
    // Only free-space cells are computed: the corridor and the rooms, not the walls.
    const Eigen::Vector2d c = strongest1.cell_center_m(static_cast<int>(i) % strongest1.cols,
                                                       static_cast<int>(i) / strongest1.cols);
    EXPECT_EQ(std::isfinite(strongest1.rssi_dbm[i]),
              sim::world::regions_contain(f.plan.free_space, c))
        << i;
    if (!std::isfinite(strongest1.rssi_dbm[i])) continue;
    EXPECT_EQ(strongest1.rssi_dbm[i], std::max(ap0.rssi_dbm[i], ap1.rssi_dbm[i]));
    (strongest1.best_ap_id[i] == 0 ? from0 : from1)++;
  }
  EXPECT_GT(from0, 50);
  EXPECT_GT(from1, 50);
  // Near AP 0 its map is strong; the far end of the corridor is weaker.
  EXPECT_GT(ap0.at(4, 8), ap0.at(40, 2) + 15.0);

  o.ap_id = 7;
  EXPECT_THROW(sim::site::compute_radio_map(*f.model, f.plan, o), InvalidInputError);
}

TEST(RadioMap, PruningHopelessApsLeavesTheStrongestMapUnchanged) {
  Fixture f;
  MacAllocator macs(4);
  std::vector<AccessPoint> aps;
  for (int i = 0; i < 12; ++i)
    aps.push_back(make_access_point(i, {1.0 + 1.7 * i, i % 2 ? 1.0 : 4.5, 2.5}, 20, 3, 4, macs));
  PropagationModel model(f.mesh, f.plan.bounds_min_m, f.plan.bounds_max_m, std::move(aps),
                         PropagationOptions{}, 4);
  RadioMapOptions o;
  o.resolution_m = 0.25;
  const RadioMap pruned = sim::site::compute_radio_map(model, f.plan, o);
  o.prune = false;
  const RadioMap full = sim::site::compute_radio_map(model, f.plan, o);
  ASSERT_EQ(pruned.rssi_dbm.size(), full.rssi_dbm.size());
  EXPECT_EQ(std::memcmp(pruned.rssi_dbm.data(), full.rssi_dbm.data(),
                        full.rssi_dbm.size() * sizeof(float)),
            0);
  EXPECT_EQ(pruned.best_ap_id, full.best_ap_id);
}

TEST(RadioMap, WritesAReadablePngAndACsvWithOneRowPerCell) {
  Fixture f;
  RadioMapOptions o;
  o.resolution_m = 0.25;
  const RadioMap map = sim::site::compute_radio_map(*f.model, f.plan, o);
  const std::filesystem::path dir = test::scratch_folder();
  const auto png = dir / "map.png", csv = dir / "map.csv";
  sim::site::write_radio_map_png(map, f.plan, f.model->access_points(), png);
  write_radio_map_csv(map, csv);

  cairo_surface_t* img = cairo_image_surface_create_from_png(png.c_str());
  ASSERT_EQ(cairo_surface_status(img), CAIRO_STATUS_SUCCESS);
  EXPECT_GT(cairo_image_surface_get_width(img), 400);
  EXPECT_GT(cairo_image_surface_get_height(img), 100);
  cairo_surface_destroy(img);

  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "x_m,y_m,rssi_dbm,ap_id");
  std::size_t rows = 0;
  while (std::getline(in, line)) ++rows;
  std::size_t computed = 0;
  for (float v : map.rssi_dbm) computed += std::isfinite(v);
  EXPECT_EQ(rows, computed);
  EXPECT_GT(computed, static_cast<std::size_t>(map.cols) * map.rows / 2);
  EXPECT_FALSE(std::filesystem::exists(dir / "map.png.partial"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace wifislam::radio_model
