#pragma once
// Scene -> floor plan (CGAL polygon booleans) -> 3-D mesh, plus the robot's smooth route.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "sim/scene/scene.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::world {

/// Builds the world of a validated scene. Deterministic: the same scene (seed included) gives a
/// bit-identical world. Throws InvalidInputError for a scene that cannot be built (e.g. a route
/// that cannot keep `min_wall_clearance_m` from the walls, disconnected free space).
World generate_world(const scene::Scene& scene);

/// The world of a dataset, from its scene.yaml (the resolved scene, seed included), for pictures
/// over its plan. nullopt, with the reason in `why_not`, when the dataset has no scene.yaml or it
/// cannot be built.
std::optional<World> dataset_world(const std::filesystem::path& dataset_dir, std::string& why_not);

/// FNV-1a hash over every vertex, uv, normal and triangle attribute (determinism checks).
std::uint64_t mesh_hash(const Mesh& mesh);

struct WorldSummary {
  double free_area_m2 = 0;      // all free space (corridors, open areas, rooms)
  double walkable_area_m2 = 0;  // corridors and open areas
  double wall_length_m = 0;     // total length of wall faces / 2 (each wall has two faces)
  std::size_t triangles = 0;
  std::size_t rooms = 0;
  std::size_t doors = 0;
  double route_length_m = 0;
  std::string to_text() const;  // human-readable, one item per line
};
WorldSummary summarize_world(const World& world);

}  // namespace wifislam::sim::world
