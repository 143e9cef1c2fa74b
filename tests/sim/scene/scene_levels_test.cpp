// Scenes of several levels (scene key `levels:`): defaults, one level's part, and every new
// mistake reported at its file:line:column with the key path the file has.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "sim/scene/scene_levels.hpp"
#include "sim/scene/scene_loader.hpp"
#include "tests/sim/scene/scene_text.hpp"

namespace wifislam::sim {
namespace {

// Two storeys of one corridor each, the second above the first; line numbers matter below.
const char* kTwoLevels = R"(version: 1
building: {wall_height_m: 2.8}
levels:
  - {id: ground}
  - {id: first, slab_thickness_m: 0.25}
nodes:
  - {id: A, position_m: [0, 0]}
  - {id: B, position_m: [12, 0]}
  - {id: A1, position_m: [0, 0], level: first}
  - {id: B1, position_m: [12, 0], level: first}
corridors:
  - {id: ab, from: A, to: B}
  - {id: ab1, from: A1, to: B1}
access_points:
  placement: explicit
  list:
    - {position_m: [6, 0, 2.5], level: first}
    - {position_m: [2, 0, 2.5]}
route:
  nodes: [A, B]
)";

ParseError expect_levels_parse_error(const std::string& yaml) {
  return test::expect_parse_error(yaml, "levels.yaml");
}

using test::replace;

bool mentions(const ParseError& e, const std::string& part) {
  return std::string(e.what()).find(part) != std::string::npos;
}

TEST(SceneLevels, DefaultsStackEachLevelOnTheOneBelowAndAreWrittenIntoTheScene) {
  const scene::Scene scene = scene::load_scene_yaml(kTwoLevels, "levels.yaml");
  const std::vector<scene::ResolvedLevel> levels = scene::resolved_levels(scene);
  ASSERT_EQ(levels.size(), 2u);
  EXPECT_EQ(levels[0].elevation_m, 0.0);
  EXPECT_DOUBLE_EQ(levels[0].storey_height_m, 2.8 + 0.25);  // walls up to the slab above
  EXPECT_DOUBLE_EQ(levels[1].elevation_m, 3.05);
  EXPECT_DOUBLE_EQ(levels[1].storey_height_m, 2.8 + 0.25);
  EXPECT_EQ(levels[1].slab_material, radio_model::WallMaterial::kConcrete);
  // The resolved scene states them, and reads back to the same levels.
  const scene::Scene again =
      scene::load_scene_yaml(scene::resolved_scene_yaml(scene), "resolved.yaml");
  ASSERT_EQ(again.levels.size(), 2u);
  EXPECT_EQ(again.levels[1].elevation_m, scene.levels[1].elevation_m);
  EXPECT_EQ(again.levels[1].storey_height_m, scene.levels[1].storey_height_m);
  EXPECT_EQ(scene::route_level(scene), "ground");
}

TEST(SceneLevels, ALevelsPartHoldsItsOwnPiecesRenumberedWithTheFilesKeys) {
  const scene::Scene scene = scene::load_scene_yaml(kTwoLevels, "levels.yaml");
  const scene::Scene first = scene::scene_on_level(scene, "first");
  ASSERT_EQ(first.nodes.size(), 2u);
  EXPECT_EQ(first.nodes[0].id, "A1");
  ASSERT_EQ(first.corridors.size(), 1u);
  EXPECT_EQ(first.corridors[0].id, "ab1");
  ASSERT_EQ(first.access_points.explicit_list.size(), 1u);
  EXPECT_EQ(first.access_points.count, 1);
  EXPECT_TRUE(first.levels.empty());
  // A problem found in the part is reported at the file's item, key and line.
  try {
    first.reject("nodes[0].position_m", "test");
    FAIL() << "reject returned";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.key_path(), "nodes[2].position_m");
    EXPECT_EQ(e.where(), "levels.yaml:9:26");
  }
  const scene::Scene ground = scene::scene_on_level(scene, "ground");
  EXPECT_EQ(ground.nodes.size(), 2u);
  EXPECT_EQ(ground.access_points.explicit_list.size(), 1u);
}

TEST(SceneLevels, NodesOfDifferentLevelsMayStandOneAboveTheOther) {
  // A1 and A share (0, 0): allowed across levels, refused on one.
  EXPECT_NO_THROW(scene::load_scene_yaml(kTwoLevels, "levels.yaml"));
  const auto e = expect_levels_parse_error(replace(
      kTwoLevels, "{id: A1, position_m: [0, 0], level: first}", "{id: A1, position_m: [0, 0]}"));
  EXPECT_EQ(e.key_path(), "nodes[2].position_m");
}

TEST(SceneLevels, OverlappingLevelsAreLocated) {
  const auto e =
      expect_levels_parse_error(replace(kTwoLevels, "{id: first, slab_thickness_m: 0.25}",
                                        "{id: first, slab_thickness_m: 0.25, elevation_m: 2.9}"));
  EXPECT_EQ(e.key_path(), "levels[1].elevation_m");
  EXPECT_EQ(e.where(), "levels.yaml:5:54");
  EXPECT_TRUE(mentions(e, "overlaps level 'ground'")) << e.what();
}

TEST(SceneLevels, AStoreyLowerThanItsWallsIsLocated) {
  const auto e = expect_levels_parse_error(
      replace(kTwoLevels, "{id: ground}", "{id: ground, storey_height_m: 2.5}"));
  EXPECT_EQ(e.key_path(), "levels[0].storey_height_m");
}

TEST(SceneLevels, AnAccessPointOnAMissingLevelIsLocated) {
  const auto e = expect_levels_parse_error(
      replace(kTwoLevels, "[6, 0, 2.5], level: first", "[6, 0, 2.5], level: second"));
  EXPECT_EQ(e.key_path(), "access_points.list[0].level");
  EXPECT_EQ(e.where(), "levels.yaml:17:40");
  EXPECT_TRUE(mentions(e, "no level 'second' (levels: 'ground', 'first')")) << e.what();
}

TEST(SceneLevels, ALevelNamedInASceneWithoutLevelsIsLocated) {
  std::string one_level = kTwoLevels;
  for (const char* line :
       {"levels:\n", "  - {id: ground}\n", "  - {id: first, slab_thickness_m: 0.25}\n",
        "  - {id: A1, position_m: [0, 0], level: first}\n",
        "  - {id: B1, position_m: [12, 0], level: first}\n", "  - {id: ab1, from: A1, to: B1}\n"})
    one_level = replace(one_level, line, "");
  const auto e = expect_levels_parse_error(one_level);
  EXPECT_EQ(e.key_path(), "access_points.list[0].level");
  EXPECT_TRUE(mentions(e, "the scene has no `levels:`")) << e.what();
}

TEST(SceneLevels, ARouteAcrossLevelsIsLocated) {
  const auto e =
      expect_levels_parse_error(replace(kTwoLevels, "nodes: [A, B]\n", "nodes: [A, B, B1]\n"));
  EXPECT_EQ(e.key_path(), "route.nodes[2]");
  EXPECT_TRUE(mentions(e, "node 'B1' is on level 'first', the route on level 'ground'"))
      << e.what();
}

TEST(SceneLevels, ACorridorAcrossLevelsIsLocated) {
  const auto e = expect_levels_parse_error(
      replace(kTwoLevels, "{id: ab1, from: A1, to: B1}", "{id: ab1, from: A1, to: B}"));
  EXPECT_EQ(e.key_path(), "corridors[1].to");
  EXPECT_TRUE(mentions(e, "a corridor stays on one level")) << e.what();
}

TEST(SceneLevels, ALevelWithoutAPlanIsLocated) {
  const auto e = expect_levels_parse_error(
      replace(kTwoLevels, "  - {id: first, slab_thickness_m: 0.25}\n",
              "  - {id: first, slab_thickness_m: 0.25}\n  - {id: roof}\n"));
  EXPECT_EQ(e.key_path(), "levels[2]");
  EXPECT_TRUE(mentions(e, "level 'roof' has no corridors' nodes and no spaces")) << e.what();
}

TEST(SceneLevels, EachLevelsCorridorGraphIsConnectedOnItsOwn) {
  EXPECT_NO_THROW(scene::load_scene_yaml(kTwoLevels, "levels.yaml"));
  const auto e = expect_levels_parse_error(
      replace(replace(kTwoLevels, "  - {id: B1, position_m: [12, 0], level: first}\n",
                      "  - {id: B1, position_m: [12, 0], level: first}\n  - {id: C1, position_m: "
                      "[30, 0], level: first}\n  - {id: D1, position_m: [40, 0], level: first}\n"),
              "  - {id: ab1, from: A1, to: B1}\n",
              "  - {id: ab1, from: A1, to: B1}\n  - {id: cd1, from: C1, to: D1}\n"));
  EXPECT_EQ(e.key_path(), "nodes[4]");
  EXPECT_TRUE(mentions(e, "cannot be reached from node 'A1'")) << e.what();
}

}  // namespace
}  // namespace wifislam::sim
