#pragma once
// A small generated world for the SLAM tests: an 8 x 6 m square loop of 2 m corridors with every
// wall segment looking different (aliasing 0) and plenty of posters, so a loop closure is
// visually unambiguous. Short, so the end-to-end tests stay fast.

#include <string>

#include "sim/scene/scene.hpp"

namespace wifislam::test {

/// The YAML text of the scene (route: once around the loop and a few metres further).
std::string small_loop_scene_yaml();
sim::scene::Scene small_loop_scene();
/// The same loop with 6 s pauses: long enough for a few Wi-Fi scans each (the plain one pauses
/// 1 s, shorter than one scan, so it has no Wi-Fi at all).
std::string small_loop_with_wifi_scene_yaml();
sim::scene::Scene small_loop_with_wifi_scene();

}  // namespace wifislam::test
