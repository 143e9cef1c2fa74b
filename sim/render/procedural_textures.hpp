#pragma once
// Procedural surface textures, generated deterministically from the scene seed, the theme name,
// the surface kind and the appearance variant (one seed, one look: datasets are byte-identical).
//
// Appearance variant 0 is the shared look: every wall segment with variant 0 gets the very same
// texture, so at aliasing 1.0 two corridor segments render (near-)identical images. A variant
// k > 0 is a look of its own (other paint tint, other wall markings), and posters are drawn from
// (decoration, variant), so at aliasing 0.0 every segment has unique posters and markings.
//
// Images are drawn upright (row 0 = top) with OpenCV's drawing functions; texture coordinate v
// grows upwards (v = height on walls), which the uploader handles by flipping rows.

#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "sim/scene/scene.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::render {

/// Which texture a triangle uses.
struct TextureKey {
  world::SurfaceKind surface = world::SurfaceKind::kWall;
  int variant = 0;
  int decoration = -1;  // posters only
  friend auto operator<=>(const TextureKey&, const TextureKey&) = default;
};

/// The key of a mesh triangle: folds the attributes a surface kind ignores, so that e.g. all
/// lights share one texture.
TextureKey texture_key_of(const world::Triangle& triangle);

struct TextureImage {
  cv::Mat bgr;  // CV_8UC3, row 0 = top of the image
  /// Tiling textures: size of one image in metres of (u, v). Ignored when `fit_to_face`.
  double period_u_m = 1.0, period_v_m = 1.0;
  /// True: the image covers each planar face of the surface once (posters, doors, lights).
  bool fit_to_face = false;
  /// Light-emitting surface (ceiling lights): rendered unlit and bright.
  bool emissive = false;
};

class ProceduralTextures {
 public:
  /// Throws InvalidInputError when a theme name is unknown (known: wall painted|brick,
  /// door wood|painted, floor tiles|carpet, ceiling panels|plain).
  ProceduralTextures(std::uint64_t seed, const scene::AppearanceThemes& themes);

  TextureImage make(const TextureKey& key) const;

  static const std::vector<std::string>& wall_themes();
  static const std::vector<std::string>& door_themes();
  static const std::vector<std::string>& floor_themes();
  static const std::vector<std::string>& ceiling_themes();

 private:
  std::uint64_t seed_;
  scene::AppearanceThemes themes_;
};

}  // namespace wifislam::sim::render
