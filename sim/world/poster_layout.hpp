#pragma once
// Posters and explicit landmarks on the walls.
//
// Posters are laid out per appearance segment from the segment's variant: the layout (how many,
// where along the segment, which design) is drawn from Rng::stream(seed, "appearance/posters/<v>")
// for variant v, so every segment with the shared look (v = 0) carries the same posters at the same
// relative places, and every unique segment its own. Expected count per segment:
// `posters_per_10m` x `segment_length_m` / 10. Designs: shared-look posters draw an index in
// [0, 1000); unique ones use 1000 + 16 v + j (j-th poster of the segment); explicit landmarks use
// 1 000 000 + their index in the scene.

#include <vector>

#include <Eigen/Core>

#include "sim/scene/scene.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::world {

struct PosterPlacement {
  int face_index = -1;                                 // into FloorPlan::wall_faces
  Eigen::Vector2d center_m = Eigen::Vector2d::Zero();  // on the face line
  Eigen::Vector2d along = Eigen::Vector2d::UnitX();    // face direction (a -> b)
  Eigen::Vector2d normal = Eigen::Vector2d::UnitY();   // into free space
  double center_height_m = 1.5;
  double width_m = 0.6;
  double height_m = 0.85;
  int decoration = 0;
  int appearance_variant = 0;
  bool landmark = false;
};

std::vector<PosterPlacement> place_posters(const scene::Scene& scene, const FloorPlan& plan);

}  // namespace wifislam::sim::world
