// The paper's Fig. 2 on the shipped scenes: Wi-Fi signature similarity falls with distance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "radio_model/propagation_model.hpp"
#include "radio_model/radio_map.hpp"
#include "radio_model/wifi_scanner.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/site/ap_placement.hpp"
#include "sim/site/radio_map_over_plan.hpp"
#include "sim/site/radio_options.hpp"
#include "sim/world/radio_wall_mesh.hpp"
#include "sim/world/world_generator.hpp"
#include "tests/radio_model/pause_signatures.hpp"

namespace wifislam::radio_model {
namespace {

constexpr double kPauseSpacingM = 3.5;
constexpr int kScansPerPause = 5;  // ~10 s pause at one scan per 2 s

double scene_spearman(const std::string& file, std::size_t* pause_count = nullptr) {
  const sim::scene::Scene scene =
      sim::scene::load_scene_file(std::string(WIFISLAM_SCENES_DIR) + "/" + file);
  const sim::world::World world = sim::world::generate_world(scene);
  PropagationModel model(sim::world::radio_wall_mesh(world.mesh), world.plan.bounds_min_m,
                         world.plan.bounds_max_m, sim::site::make_access_points(scene, world.plan),
                         sim::site::propagation_options(scene), scene.seed);
  WifiScanner scanner(model, sim::site::wifi_scanner_options(scene.sensors.wifi), scene.seed);
  const auto pauses = test::pauses_along_route(world.route, scanner, kPauseSpacingM, kScansPerPause,
                                               scene.sensors.camera.height_m);
  if (pause_count) *pause_count = pauses.size();
  return test::distance_similarity_spearman(pauses);
}

TEST(WifiSimilarity, SimilarityFallsWithDistanceOnCHallAsInThePapersFigure2) {
  std::size_t pauses = 0;
  const double rho = scene_spearman("c_hall.yaml", &pauses);
  std::cout << "c_hall: " << pauses << " pauses, Spearman(distance, similarity) = " << rho << "\n";
  RecordProperty("spearman_c_hall", std::to_string(rho));
  EXPECT_GT(pauses, 40u);
  EXPECT_LE(rho, -0.6);
}

TEST(RadioMapOnCHall, PrunedStrongestMapEqualsTheFullOne) {
  const sim::scene::Scene scene =
      sim::scene::load_scene_file(std::string(WIFISLAM_SCENES_DIR) + "/c_hall.yaml");
  const sim::world::World world = sim::world::generate_world(scene);
  PropagationModel model(sim::world::radio_wall_mesh(world.mesh), world.plan.bounds_min_m,
                         world.plan.bounds_max_m, sim::site::make_access_points(scene, world.plan),
                         sim::site::propagation_options(scene), scene.seed);
  RadioMapOptions o;
  o.resolution_m = 0.5;
  const RadioMap pruned = sim::site::compute_radio_map(model, world.plan, o);
  o.prune = false;
  const RadioMap full = sim::site::compute_radio_map(model, world.plan, o);
  ASSERT_EQ(pruned.rssi_dbm.size(), full.rssi_dbm.size());
  EXPECT_EQ(std::memcmp(pruned.rssi_dbm.data(), full.rssi_dbm.data(),
                        full.rssi_dbm.size() * sizeof(float)),
            0);
  EXPECT_EQ(pruned.best_ap_id, full.best_ap_id);
  std::size_t computed = 0;
  for (float v : full.rssi_dbm) computed += std::isfinite(v);
  EXPECT_GT(computed, full.rssi_dbm.size() / 3);
}

TEST(WifiSimilarity, SimilarityFallsWithDistanceOnEveryShippedScene) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(WIFISLAM_SCENES_DIR))
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty());
  for (const auto& path : files) {
    const std::string file = path.filename().string();
    SCOPED_TRACE(file);
    std::size_t pauses = 0;
    const double rho = scene_spearman(file, &pauses);
    std::cout << file << ": " << pauses << " pauses, Spearman(distance, similarity) = " << rho
              << "\n";
    RecordProperty("spearman_" + path.stem().string(), std::to_string(rho));
    EXPECT_LE(rho, -0.6) << file;
  }
}

}  // namespace
}  // namespace wifislam::radio_model
