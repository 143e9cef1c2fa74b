#include "tests/slam/slam_test_scene.hpp"

#include "sim/scene/scene_loader.hpp"
#include "tests/support/square_loop_scene.hpp"

namespace wifislam::test {

std::string small_loop_scene_yaml() {
  return square_loop_yaml(
      {.name = "slam_small_loop",
       .description = "Small square loop with unique wall looks, for SLAM tests.",
       .seed = 77,
       .east_m = 8,
       .north_m = 6,
       .route = "A, B, C, D, A, B"});
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
