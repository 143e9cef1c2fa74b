#pragma once
// The scene `wifislam demo` runs when given none: a small rectangular loop of corridors with a
// row of offices, short enough that the whole demo finishes in a few minutes on 2 cores.

namespace wifislam::cli {

inline constexpr const char* kDemoSceneYaml = R"(version: 1
name: demo_loop
description: Small loop of corridors with offices, embedded in the wifislam binary for the demo.
seed: 7
building: {wall_height_m: 2.8, wall_thickness_m: 0.15}
nodes:
  - {id: A, position_m: [0, 0]}
  - {id: B, position_m: [14, 0]}
  - {id: C, position_m: [14, 9]}
  - {id: D, position_m: [0, 9]}
corridors:
  - id: south
    from: A
    to: B
    width_m: 2.0
    rooms: [{side: right, from_m: 1.2, to_m: 12.8, room_length_m: 3.8, depth_m: 4.0}]
  - {id: east, from: B, to: C, width_m: 2.0}
  - id: north
    from: C
    to: D
    width_m: 2.0
    rooms: [{side: right, from_m: 1.2, to_m: 12.8, room_length_m: 3.8, depth_m: 4.0}]
  - {id: west, from: D, to: A, width_m: 2.0}
appearance: {aliasing: 0.3, posters_per_10m: 2.0}
access_points: {placement: rooms, count: 12}
route:
  nodes: [A, B, C, D, A, B]
  speed_mps: 0.5
  pause: {spacing_m: [3.0, 4.0], duration_s: 6.0}
sensors:
  camera: {fps: 10}
radio: {environment: office}
)";

}  // namespace wifislam::cli
