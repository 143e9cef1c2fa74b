#pragma once
// Where the access points go, from the scene's `access_points` block and the floor plan:
//   explicit  the listed positions;
//   grid      a regular cols x rows grid over the plan's bounds (cols/rows follow its aspect),
//             each node moved to the nearest free-space spot;
//   random    uniformly random free-space spots at least `min_spacing_m` apart;
//   rooms     as in real buildings: three quarters of the APs (rounded up) in rooms off the
//             corridors (random rooms, a random spot in each), the rest in the corridors and
//             halls; when there are too few rooms the corridors take the remainder;
//   colinear  evenly spaced on the segment line_from_m -> line_to_m (ends included).
// Generated positions keep 0.4 m from every wall face and stand at `height_m`. Deterministic from
// `access_points.seed` (default: the scene seed).

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "radio_model/access_point.hpp"
#include "sim/scene/scene.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::site {

/// AP positions (x, y, z). Throws InvalidInputError when the plan has no room for them or the
/// placement's parameters are unusable (e.g. colinear with line_from_m == line_to_m).
std::vector<Eigen::Vector3d> place_access_point_positions(const scene::AccessPoints& spec,
                                                          const world::FloorPlan& plan,
                                                          std::uint64_t seed);

/// Where an access point could stand, for placement studies (`wifislam study place`): free-space
/// spots (rooms, corridors and halls) 0.4 m off the wall faces, as the placements take them,
/// thinned in lattice order so that no two are closer than `spacing_m`. Deterministic; (x, y) only.
std::vector<Eigen::Vector2d> access_point_candidate_spots(const world::FloorPlan& plan,
                                                          double spacing_m);

/// The scene's access points with their BSSIDs; ids 0..n-1 in placement order. A placement that
/// cannot be done is rejected at the scene's `access_points` key (Scene::reject).
std::vector<radio_model::AccessPoint> make_access_points(const scene::Scene& scene,
                                                         const world::FloorPlan& plan);

/// The building's access points as placed: make_access_points(scene, world.plan) for a one-level
/// world; else each storey's, lowest first, placed on its own plan (generated placements put
/// `count` on every level) and raised to its elevation: z is in the building's frame. Ids run on.
std::vector<radio_model::AccessPoint> placed_access_points(const scene::Scene& scene,
                                                           const world::World& world);

/// The building's access points in the scene's session: placed_access_points with the changes
/// up to that session applied (sim/site/ap_changes.hpp).
std::vector<radio_model::AccessPoint> make_access_points(const scene::Scene& scene,
                                                         const world::World& world);

/// The seed the access points derive from: `access_points.seed`, else the scene seed.
std::uint64_t access_point_seed(const scene::Scene& scene);

}  // namespace wifislam::sim::site
