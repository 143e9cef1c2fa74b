#pragma once
// Scenes built in code for the world tests, and the invariants every generated world must meet
// (checked for these scenes and for every shipped scene file).

#include "sim/scene/scene.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::test {

/// A square loop of four corridors A(0,0) B(side,0) C(side,side) D(0,side), rooms outside the
/// loop along every corridor and inside along the south corridor, route A B C D A.
sim::scene::Scene square_loop_scene(double side_m = 14.0, double width_m = 2.0,
                                    bool doors_open = false);

/// Expects (GoogleTest) the floor-plan invariants: one walkable piece; every free-space piece
/// reachable or a room behind a closed door; rooms clear of corridors and of each other; wall
/// faces with free space (or outside) on the left and wall on the right; open doors open and
/// closed doors blocked by a kWoodDoor wall; the route inside walkable space with clearance.
void expect_plan_invariants(const sim::scene::Scene& scene, const sim::world::World& world);

/// Expects the mesh invariants: closed wall solids with consistently oriented triangles, normals
/// into free space, no degenerate triangles, texture coordinates in metres.
void expect_mesh_invariants(const sim::world::World& world);

}  // namespace wifislam::test
