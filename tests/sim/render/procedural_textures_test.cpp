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
  const ProceduralTextures a(9, AppearanceThemes{}), b(9, AppearanceThemes{});
  for (SurfaceKind kind : {SurfaceKind::kWall, SurfaceKind::kFloor, SurfaceKind::kCeiling,
                           SurfaceKind::kDoor, SurfaceKind::kPoster, SurfaceKind::kLight}) {
    const TextureKey key{kind, 0, kind == SurfaceKind::kPoster ? 3 : -1};
    EXPECT_EQ(cv::norm(a.make(key).bgr, b.make(key).bgr, cv::NORM_INF), 0.0);
  }
}

TEST(ProceduralTextures, UniqueVariantsAndSeedsLookDifferent) {
  const ProceduralTextures textures(9, AppearanceThemes{});
  const cv::Mat shared = textures.make({SurfaceKind::kWall, 0, -1}).bgr;
  const cv::Mat one = textures.make({SurfaceKind::kWall, 1, -1}).bgr;
  const cv::Mat two = textures.make({SurfaceKind::kWall, 2, -1}).bgr;
  EXPECT_GT(mean_abs_difference(shared, one), 2.0);
  EXPECT_GT(mean_abs_difference(one, two), 2.0);
  const ProceduralTextures other_seed(10, AppearanceThemes{});
  EXPECT_GT(mean_abs_difference(shared, other_seed.make({SurfaceKind::kWall, 0, -1}).bgr), 2.0);
  // Posters: the design index and the variant both pick the design.
  const cv::Mat p1 = textures.make({SurfaceKind::kPoster, 0, 1}).bgr;
  const cv::Mat p2 = textures.make({SurfaceKind::kPoster, 0, 2}).bgr;
  EXPECT_GT(mean_abs_difference(p1, p2), 10.0);
}

TEST(ProceduralTextures, LayoutFollowsTheSurfaceKind) {
  const ProceduralTextures textures(9, AppearanceThemes{});
  EXPECT_FALSE(textures.make({SurfaceKind::kWall, 0, -1}).fit_to_face);
  EXPECT_DOUBLE_EQ(textures.make({SurfaceKind::kWall, 0, -1}).period_u_m, 4.0);
  EXPECT_TRUE(textures.make({SurfaceKind::kPoster, 0, 1}).fit_to_face);
  EXPECT_TRUE(textures.make({SurfaceKind::kDoor, 0, -1}).fit_to_face);
  EXPECT_TRUE(textures.make({SurfaceKind::kLight, 0, -1}).emissive);
  // Lights and wall tops ignore the variant: one look everywhere.
  Triangle light;
  light.surface = SurfaceKind::kLight;
  light.appearance_variant = 5;
  EXPECT_EQ(texture_key_of(light).variant, 0);
}

TEST(ProceduralTextures, EveryThemeBuildsAndUnknownThemesAreNamed) {
  for (const std::string& wall : ProceduralTextures::wall_themes()) {
    for (const std::string& floor : ProceduralTextures::floor_themes()) {
      AppearanceThemes themes;
      themes.wall = wall;
      themes.floor = floor;
      const ProceduralTextures textures(1, themes);
      EXPECT_FALSE(textures.make({SurfaceKind::kWall, 1, -1}).bgr.empty());
      EXPECT_FALSE(textures.make({SurfaceKind::kFloor, 1, -1}).bgr.empty());
    }
  }
  AppearanceThemes bad;
  bad.ceiling = "mirrors";
  try {
    ProceduralTextures textures(1, bad);
    FAIL() << "expected InvalidInputError";
  } catch (const InvalidInputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("appearance.themes.ceiling"), std::string::npos) << message;
    EXPECT_NE(message.find("mirrors"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace wifislam::sim
