#pragma once
// The scene most tests run: a small square loop of four 2 m corridors with distinct walls
// (aliasing 0, posters every 2.5 m), eight random access points and short pauses. A world, a
// renderer and a radio model build in well under a second, and a few frames a second give SLAM
// and eval a short real run. Tests differ only in its size, seed, route and name.

#include <string>

namespace wifislam::test {

struct SquareLoop {
  std::string name;
  std::string description;
  int seed = 91;
  int east_m = 7;   // corner B is at (east_m, 0), C at (east_m, north_m)
  int north_m = 5;  // corner D is at (0, north_m)
  std::string route = "A, B, C, D, A";
};

/// The loop as scene YAML (scenes/README.md's schema).
inline std::string square_loop_yaml(const SquareLoop& loop) {
  const std::string e = std::to_string(loop.east_m), n = std::to_string(loop.north_m);
  return "version: 1\nname: " + loop.name + "\ndescription: " + loop.description +
         "\nseed: " + std::to_string(loop.seed) +
         R"(
building: {wall_height_m: 2.8, wall_thickness_m: 0.15}
nodes:
  - {id: A, position_m: [0, 0]}
  - {id: B, position_m: [)" +
         e + R"(, 0]}
  - {id: C, position_m: [)" +
         e + ", " + n + R"(]}
  - {id: D, position_m: [0, )" +
         n + R"(]}
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
  nodes: [)" +
         loop.route + R"(]
  speed_mps: 0.5
  pause: {spacing_m: [3.0, 4.0], duration_s: 1.0}
radio: {environment: office}
)";
}

}  // namespace wifislam::test
