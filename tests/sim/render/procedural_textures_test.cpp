// Textures are deterministic functions of (seed, theme, kind, variant, decoration); the shared
// variant is one look, unique variants differ.

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "sim/render/procedural_textures.hpp"

namespace wifislam::sim {
namespace {

double mean_abs_difference(const cv::Mat& a, const cv::Mat& b) {
  return cv::norm(a, b, cv::NORM_L1) / static_cast<double>(a.total() * a.channels());
}

TEST(ProceduralTextures, SameKeySameSeedGivesTheSameImage) {
  const render::ProceduralTextures a(9, scene::AppearanceThemes{}), b(9, scene::AppearanceThemes{});
  for (world::SurfaceKind kind :
       {world::SurfaceKind::kWall, world::SurfaceKind::kFloor, world::SurfaceKind::kCeiling,
        world::SurfaceKind::kDoor, world::SurfaceKind::kPoster, world::SurfaceKind::kLight}) {
    const render::TextureKey key{kind, 0, kind == world::SurfaceKind::kPoster ? 3 : -1};
    EXPECT_EQ(cv::norm(a.make(key).bgr, b.make(key).bgr, cv::NORM_INF), 0.0);
  }
}

TEST(ProceduralTextures, UniqueVariantsAndSeedsLookDifferent) {
  const render::ProceduralTextures textures(9, scene::AppearanceThemes{});
  const cv::Mat shared = textures.make({world::SurfaceKind::kWall, 0, -1}).bgr;
  const cv::Mat one = textures.make({world::SurfaceKind::kWall, 1, -1}).bgr;
  const cv::Mat two = textures.make({world::SurfaceKind::kWall, 2, -1}).bgr;
  EXPECT_GT(mean_abs_difference(shared, one), 2.0);
  EXPECT_GT(mean_abs_difference(one, two), 2.0);
  const render::ProceduralTextures other_seed(10, scene::AppearanceThemes{});
  EXPECT_GT(mean_abs_difference(shared, other_seed.make({world::SurfaceKind::kWall, 0, -1}).bgr),
            2.0);
  // Posters: the design index and the variant both pick the design.
  const cv::Mat p1 = textures.make({world::SurfaceKind::kPoster, 0, 1}).bgr;
  const cv::Mat p2 = textures.make({world::SurfaceKind::kPoster, 0, 2}).bgr;
  EXPECT_GT(mean_abs_difference(p1, p2), 10.0);
}

TEST(ProceduralTextures, LayoutFollowsTheSurfaceKind) {
  const render::ProceduralTextures textures(9, scene::AppearanceThemes{});
  EXPECT_FALSE(textures.make({world::SurfaceKind::kWall, 0, -1}).fit_to_face);
  EXPECT_DOUBLE_EQ(textures.make({world::SurfaceKind::kWall, 0, -1}).period_u_m, 4.0);
  EXPECT_TRUE(textures.make({world::SurfaceKind::kPoster, 0, 1}).fit_to_face);
  EXPECT_TRUE(textures.make({world::SurfaceKind::kDoor, 0, -1}).fit_to_face);
  EXPECT_TRUE(textures.make({world::SurfaceKind::kLight, 0, -1}).emissive);
  // Lights and wall tops ignore the variant: one look everywhere.
  world::Triangle light;
  light.surface = world::SurfaceKind::kLight;
  light.appearance_variant = 5;
  EXPECT_EQ(render::texture_key_of(light).variant, 0);
}

TEST(ProceduralTextures, EveryThemeBuildsAndUnknownThemesAreNamed) {
  for (const std::string& wall : render::ProceduralTextures::wall_themes()) {
    for (const std::string& floor : render::ProceduralTextures::floor_themes()) {
      scene::AppearanceThemes themes;
      themes.wall = wall;
      themes.floor = floor;
      const render::ProceduralTextures textures(1, themes);
      EXPECT_FALSE(textures.make({world::SurfaceKind::kWall, 1, -1}).bgr.empty());
      EXPECT_FALSE(textures.make({world::SurfaceKind::kFloor, 1, -1}).bgr.empty());
    }
  }
  scene::AppearanceThemes bad;
  bad.ceiling = "mirrors";
  try {
    render::ProceduralTextures textures(1, bad);
    FAIL() << "expected InvalidInputError";
  } catch (const InvalidInputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("appearance.themes.ceiling"), std::string::npos) << message;
    EXPECT_NE(message.find("mirrors"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace wifislam::sim
