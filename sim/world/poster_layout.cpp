#include "sim/world/poster_layout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/rng.hpp"
#include "sim/world/plan_queries.hpp"

namespace wifislam::sim::world {

namespace {

constexpr double kPosterWidthM = 0.6;
constexpr double kPosterHeightM = 0.85;
constexpr double kPosterCenterHeightM = 1.5;
constexpr double kEndMarginM = 0.15;  // keeps posters off corners and door frames

bool can_carry_poster(const WallFace2& f) { return !f.exterior && f.door_index < 0; }

PosterPlacement on_face(const FloorPlan& plan, int face_index, double along_m) {
  const WallFace2& f = plan.wall_faces[face_index];
  PosterPlacement p;
  p.face_index = face_index;
  p.along = (f.b_m - f.a_m).normalized();
  p.normal = Eigen::Vector2d(-p.along.y(), p.along.x());
  p.center_m = f.a_m + along_m * p.along;
  p.appearance_variant =
      f.appearance_segment >= 0 ? plan.appearance_segments[f.appearance_segment].variant : 0;
  return p;
}

}  // namespace

std::vector<PosterPlacement> place_posters(const scene::Scene& scene, const FloorPlan& plan) {
  std::vector<PosterPlacement> posters;
  const double expected =
      std::max(0.0, scene.appearance.posters_per_10m) * scene.appearance.segment_length_m / 10.0;
  const double max_height = plan.wall_height_m - 0.05;
  for (std::size_t i = 0; i < plan.wall_faces.size(); ++i) {
    const WallFace2& f = plan.wall_faces[i];
    if (!can_carry_poster(f) || f.appearance_segment < 0) continue;
    const int variant = plan.appearance_segments[f.appearance_segment].variant;
    Rng rng = Rng::stream(scene.seed, "appearance/posters/" + std::to_string(variant));
    const int whole = static_cast<int>(std::floor(expected));
    const int count = whole + (rng.bernoulli(expected - whole) ? 1 : 0);
    // Draw the whole layout first so it never depends on this face's length.
    std::vector<double> offsets(count);
    std::vector<int> designs(count);
    for (int j = 0; j < count; ++j) {
      offsets[j] = rng.uniform();
      designs[j] =
          variant == 0 ? static_cast<int>(rng.uniform_int(0, 999)) : 1000 + 16 * variant + j;
    }
    const double length = (f.b_m - f.a_m).norm();
    const double usable = length - 2 * kEndMarginM;
    if (count == 0 || usable < kPosterWidthM) continue;
    const double slot = usable / count;
    if (slot < kPosterWidthM) continue;
    for (int j = 0; j < count; ++j) {
      const double along =
          kEndMarginM + j * slot + 0.5 * kPosterWidthM + offsets[j] * (slot - kPosterWidthM);
      PosterPlacement p = on_face(plan, static_cast<int>(i), along);
      p.width_m = kPosterWidthM;
      p.height_m = std::min(kPosterHeightM, max_height - 0.2);
      p.center_height_m = std::min(kPosterCenterHeightM, max_height - 0.5 * p.height_m);
      p.decoration = designs[j];
      posters.push_back(p);
    }
  }
  for (std::size_t k = 0; k < scene.appearance.landmarks.size(); ++k) {
    const scene::Landmark& mark = scene.appearance.landmarks[k];
    int best = -1;
    double best_d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < plan.wall_faces.size(); ++i) {
      const WallFace2& f = plan.wall_faces[i];
      if (!can_carry_poster(f)) continue;
      const double d = segment_distance_m(mark.position_m, f.a_m, f.b_m);
      if (d < best_d) best_d = d, best = static_cast<int>(i);
    }
    if (best < 0) continue;
    const WallFace2& f = plan.wall_faces[best];
    const double length = (f.b_m - f.a_m).norm();
    const double half = 0.5 * std::min(mark.width_m, length);
    const double along =
        std::clamp((mark.position_m - f.a_m).dot((f.b_m - f.a_m) / length), half, length - half);
    PosterPlacement p = on_face(plan, best, along);
    p.width_m = 2 * half;
    p.height_m = std::min(1.4 * mark.width_m, max_height - 0.1);
    p.center_height_m =
        std::clamp(mark.height_m, 0.5 * p.height_m + 0.01, max_height - 0.5 * p.height_m);
    p.decoration = 1000000 + static_cast<int>(k);
    p.landmark = true;
    posters.push_back(p);
  }
  return posters;
}

}  // namespace wifislam::sim::world
