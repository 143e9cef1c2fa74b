#pragma once
// A small scene for generation tests: a 10 x 6 m loop of 2 m corridors with rooms along the south
// corridor and 6 access points, so a world, renderer and radio model build in well under a second.

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "sim/scene/scene_loader.hpp"
#include "tests/support/read_file.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::test {

inline const char* kSmallSceneYaml = R"(version: 1
name: small_loop
description: Test loop with rooms on one side.
seed: 77
nodes:
  - {id: A, position_m: [0, 0]}
  - {id: B, position_m: [10, 0]}
  - {id: C, position_m: [10, 6]}
  - {id: D, position_m: [0, 6]}
corridors:
  - id: south
    from: A
    to: B
    width_m: 2.0
    rooms: [{side: right, from_m: 1.2, to_m: 8.8, room_length_m: 3.8, depth_m: 3.0}]
  - {id: east, from: B, to: C, width_m: 2.0}
  - {id: north, from: C, to: D, width_m: 2.0}
  - {id: west, from: D, to: A, width_m: 2.0}
access_points: {placement: rooms, count: 6}
route:
  nodes: [A, B, C, D, A]
  pause: {spacing_m: [3.0, 4.0], duration_s: 6.0}
)";

inline sim::scene::Scene small_scene() {
  return sim::scene::load_scene_yaml(kSmallSceneYaml, "small_loop.yaml");
}

/// A folder for `generate` to make, in a scratch folder of this test's own: it does not exist yet,
/// and neither does its ".partial" staging sibling.
inline std::filesystem::path fresh_folder(const std::string& name) {
  return scratch_folder(name) / name;
}

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

}  // namespace wifislam::test
