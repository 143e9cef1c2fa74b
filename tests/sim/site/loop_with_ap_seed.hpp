#pragma once
// A small loop whose access points have their own placement seed, as the demo's radio map once
// mishandled: it seeded the shadowing from access_points.seed, the dataset from the scene seed.
// The site tests build it in process; the radiomap command test runs it through the program.

namespace wifislam::test {

inline constexpr const char* kLoopWithApSeed = R"(version: 1
name: site_test
seed: 21
nodes:
  - {id: A, position_m: [0, 0]}
  - {id: B, position_m: [9, 0]}
  - {id: C, position_m: [9, 6]}
  - {id: D, position_m: [0, 6]}
corridors:
  - {id: s, from: A, to: B}
  - {id: e, from: B, to: C}
  - {id: n, from: C, to: D}
  - {id: w, from: D, to: A}
access_points: {placement: random, count: 5, seed: 4}
route: {nodes: [A, B, C, D, A]}
sensors: {camera: {height_m: 0.7}}
)";

}  // namespace wifislam::test
