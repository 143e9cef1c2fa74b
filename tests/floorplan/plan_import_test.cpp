// Import of the two shipped real plans against the counts their files (and ATTRIBUTION.md) state;
// the scenes load and their routes go round a loop more than once; the local projection returns a
// known point to within 1 cm.
#include <gtest/gtest.h>

#include <filesystem>

#include "floorplan/imported_scene.hpp"
#include "floorplan/local_projection.hpp"
#include "floorplan/plan_import.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/world/world_generator.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;
const fs::path kPlans = fs::path(WIFISLAM_SCENES_DIR).parent_path() / "assets" / "floorplans";

/// The route's waypoints come back to where the loop started, and the robot passes the start
/// again after the first lap (more than once through the same place).
void expect_route_revisits(const sim::Scene& scene) {
  const auto& w = scene.route.waypoints_m;
  ASSERT_GE(w.size(), 4u);
  EXPECT_LT((w.front() - w.back()).norm(), 1e-9);
  int passes = 0;
  for (std::size_t i = 1; i < w.size(); ++i) passes += (w[i] - w.front()).norm() < 1e-9;
  EXPECT_GE(passes, 2) << "two laps pass the start twice";
  const sim::World world =
      sim::generate_world(sim::load_scene_yaml(sim::resolved_scene_yaml(scene), "scene"));
  EXPECT_GT(world.route.length_m(), 50.0);
}

TEST(PlanImport, OsmSitLevelOneMatchesTheFilesCounts) {
  floorplan::ImportOptions options;
  options.level = "1";
  const floorplan::ImportedPlan plan =
      floorplan::import_plan(kPlans / "fei_uv_xalapa_osm_sit" / "fei_levels_1_2.geojson", options);
  // ATTRIBUTION.md: level=1 has 45 rooms, 3 corridors, 6 areas among its 60 ways.
  EXPECT_EQ(plan.counts.rooms, 45);
  EXPECT_EQ(plan.counts.corridors, 3);
  EXPECT_EQ(plan.counts.areas, 6);
  EXPECT_EQ(plan.levels, (std::vector<std::string>{"1", "2"}));
  // Every room and area is a space unless drawn inside another; the corridors join into fewer.
  EXPECT_GE(plan.counts.spaces, 40);
  EXPECT_LE(plan.counts.spaces, 45 + 3 + 6);
  // Doors are inferred: one per room that touches a corridor or area, one per area.
  EXPECT_GE(plan.counts.space_doors, 30);
  const sim::Scene scene = floorplan::imported_scene(plan, {});
  expect_route_revisits(scene);
}

TEST(PlanImport, WrldLevelTwoMatchesTheFilesCounts) {
  const floorplan::ImportedPlan plan =
      floorplan::import_plan(kPlans / "westport_house_wrld" / "westport-house-floor-2.geojson", {});
  // ATTRIBUTION.md: level 2 has 43 walls, 25 doors, 31 windows.
  EXPECT_EQ(plan.level, "2");
  EXPECT_EQ(plan.counts.walls, 43);
  EXPECT_EQ(plan.counts.doors, 25);
  EXPECT_EQ(plan.counts.windows, 31);
  EXPECT_EQ(plan.levels.size(), 7u);
  EXPECT_EQ(plan.counts.space_doors + plan.counts.doors_not_placed, 25);
  EXPECT_GE(plan.counts.space_doors, 20) << "most doors sit on a wall between two spaces";
  EXPECT_GT(plan.wall_thickness_m, 0.1);
  EXPECT_LT(plan.wall_thickness_m, 0.5);
  expect_route_revisits(floorplan::imported_scene(plan, {}));
}

TEST(PlanImport, ShippedScenesLoadAndBuild) {
  for (const char* name : {"fei_level_1.yaml", "westport_house_level_2.yaml"}) {
    const sim::Scene scene =
        sim::load_scene_file((fs::path(WIFISLAM_SCENES_DIR) / "real" / name).string());
    const sim::World world = sim::generate_world(scene);
    EXPECT_FALSE(scene.spaces.empty()) << name;
    EXPECT_GT(world.plan.doors.size(), 10u) << name;
    EXPECT_GT(world.route.length_m(), 100.0) << name;
  }
}

TEST(LocalProjection, RoundTripsAKnownPointToOneCentimetre) {
  // Centred on Westport House; a point 40 m east and 30 m north of the centre.
  const floorplan::LocalProjection projection(-2.978, 56.4599);
  const Eigen::Vector2d centre = projection.to_local_m({-2.978, 56.4599});
  EXPECT_LT(centre.norm(), 1e-6);
  // 1 degree of latitude is 111.3 km here; of longitude cos(56.46 deg) of the equator's 111.3 km.
  const Eigen::Vector2d p = projection.to_lon_lat_deg({40.0, 30.0});
  const Eigen::Vector2d back = projection.to_local_m(p);
  EXPECT_LT((back - Eigen::Vector2d(40.0, 30.0)).norm(), 0.01);
  EXPECT_NEAR((p.y() - 56.4599) * 111334.0, 30.0, 0.3);
  EXPECT_NEAR((p.x() + 2.978) * 111320.0 * std::cos(56.4599 * M_PI / 180), 40.0, 0.3);
}

}  // namespace
}  // namespace wifislam
