#include "tests/slam/slam_test_scene.hpp"

#include "sim/scene/scene_loader.hpp"

namespace wifislam::test {

std::string small_loop_scene_yaml() {
  return R"(version: 1
name: slam_small_loop
description: Small square loop with unique wall looks, for SLAM tests.
seed: 77
building: {wall_height_m: 2.8, wall_thickness_m: 0.15}
nodes:
  - {id: A, position_m: [0, 0]}
  - {id: B, position_m: [8, 0]}
  - {id: C, position_m: [8, 6]}
  - {id: D, position_m: [0, 6]}
corridors:
  - {id: south, from: A, to: B, width_m: 2.0}
  - {id: east, from: B, to: C, width_m: 2.0}
  - {id: north, from: C, to: D, width_m: 2.0}
  - {id: west, from: D, to: A, width_m: 2.0}
appearance:
  aliasing: 0.0
  posters_per_10m: 4.0
access_points: {placement: random, count: 8}
route:
  nodes: [A, B, C, D, A, B]
  speed_mps: 0.5
  pause: {spacing_m: [3.0, 4.0], duration_s: 1.0}
radio: {environment: office}
)";
}

sim::scene::Scene small_loop_scene() {
  return sim::scene::load_scene_yaml(small_loop_scene_yaml(), "slam_small_loop");
}

std::string small_loop_with_wifi_scene_yaml() {
  std::string yaml = small_loop_scene_yaml();
  const std::string short_pause = "duration_s: 1.0";
  yaml.replace(yaml.find(short_pause), short_pause.size(), "duration_s: 6.0");
  return yaml;
}

sim::scene::Scene small_loop_with_wifi_scene() {
  return sim::scene::load_scene_yaml(small_loop_with_wifi_scene_yaml(),
                                     "slam_small_loop_with_wifi");
}

}  // namespace wifislam::test
