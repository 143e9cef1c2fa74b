// Import of the two shipped real plans against the counts their files (and ATTRIBUTION.md) state;
// the scenes load and their routes go round a loop more than once; the local projection returns a
// known point to within 1 cm.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.hpp"
#include "floorplan/imported_scene.hpp"
#include "floorplan/local_projection.hpp"
#include "floorplan/plan_import.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/world/world_generator.hpp"
#include "tests/floorplan/shipped_plans.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;

/// The route's waypoints come back to where the loop started, and the robot passes the start
/// again after the first lap (more than once through the same place).
void expect_route_revisits(const sim::scene::Scene& scene) {
  const auto& w = scene.route.waypoints_m;
  ASSERT_GE(w.size(), 4u);
  EXPECT_LT((w.front() - w.back()).norm(), 1e-9);
  int passes = 0;
  for (std::size_t i = 1; i < w.size(); ++i) passes += (w[i] - w.front()).norm() < 1e-9;
  EXPECT_GE(passes, 2) << "two laps pass the start twice";
  const sim::world::World world = sim::world::generate_world(
      sim::scene::load_scene_yaml(sim::scene::resolved_scene_yaml(scene), "scene"));
  EXPECT_GT(world.route.length_m(), 2 * (w.front() - w[w.size() / 4]).norm());
}

TEST(PlanImport, OsmSitLevelOneMatchesTheFilesCounts) {
  floorplan::ImportOptions options;
  options.level = "1";
  const floorplan::ImportedPlan plan = floorplan::import_plan(
      test::kShippedPlans / "fei_uv_xalapa_osm_sit" / "fei_levels_1_2.geojson", options);
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
  const sim::scene::Scene scene = floorplan::imported_scene(plan, {});
  expect_route_revisits(scene);
}

TEST(PlanImport, WrldLevelTwoMatchesTheFilesCounts) {
  const floorplan::ImportedPlan plan = floorplan::import_plan(
      test::kShippedPlans / "westport_house_wrld" / "westport-house-floor-2.geojson", {});
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

// An island drawn close to the outer wall cuts a 1.5 cm strip off the hall once the partition
// has moved the hall's outline; the robot's space was in two pieces and the import failed.
TEST(PlanImport, WrldLevelOneImportsWithTheStripItsIslandCutsOffMadeSolid) {
  const floorplan::ImportedPlan plan = floorplan::import_plan(
      test::kShippedPlans / "westport_house_wrld" / "westport-house-floor-1.geojson", {});
  EXPECT_EQ(plan.level, "1");
  EXPECT_NE(fmt::format("{}", fmt::join(plan.notes, "\n")).find("1 strip(s) of free space"),
            std::string::npos)
      << fmt::format("{}", fmt::join(plan.notes, "\n"));
  expect_route_revisits(floorplan::imported_scene(plan, {}));
}

TEST(PlanImport, ShippedScenesLoadAndBuild) {
  for (const char* name : {"fei_level_1.yaml", "westport_house_level_2.yaml"}) {
    const sim::scene::Scene scene =
        sim::scene::load_scene_file((fs::path(WIFISLAM_SCENES_DIR) / "real" / name).string());
    const sim::world::World world = sim::world::generate_world(scene);
    EXPECT_FALSE(scene.spaces.empty()) << name;
    EXPECT_GT(world.plan.doors.size(), 10u) << name;
    EXPECT_GT(world.route.length_m(), 100.0) << name;
  }
}

/// A small IMDF folder: a 20 x 2.4 m walkway with two rooms north of it and one south, three
/// openings on the shared walls, one level. Coordinates in metres from (lon 0, lat 51.5).
std::filesystem::path write_imdf(const fs::path& folder) {
  fs::create_directories(folder);
  const double m_per_deg_lat = 111320.0, m_per_deg_lon = 111320.0 * std::cos(51.5 * M_PI / 180);
  auto lonlat = [&](double x, double y) {
    return fmt::format("[{:.9f},{:.9f}]", x / m_per_deg_lon, 51.5 + y / m_per_deg_lat);
  };
  auto box = [&](double x0, double y0, double x1, double y1) {
    return fmt::format("[[{},{},{},{},{}]]", lonlat(x0, y0), lonlat(x1, y0), lonlat(x1, y1),
                       lonlat(x0, y1), lonlat(x0, y0));
  };
  auto unit = [&](const std::string& id, const std::string& category, const std::string& rings) {
    return fmt::format(R"({{"type":"Feature","id":"{}","feature_type":"unit","properties":)"
                       R"({{"category":"{}","level_id":"L0","name":{{"en":"{}"}}}},)"
                       R"("geometry":{{"type":"Polygon","coordinates":{}}}}})",
                       id, category, id, rings);
  };
  auto opening = [&](double x0, double y0, double x1, double y1) {
    return fmt::format(R"({{"type":"Feature","id":"o{}{}","feature_type":"opening","properties":)"
                       R"({{"category":"pedestrian","level_id":"L0"}},"geometry":)"
                       R"({{"type":"LineString","coordinates":[{},{}]}}}})",
                       x0, y0, lonlat(x0, y0), lonlat(x1, y1));
  };
  auto collection = [](const std::vector<std::string>& features) {
    return R"({"type":"FeatureCollection","features":[)" +
           fmt::format("{}", fmt::join(features, ",")) + "]}";
  };
  std::ofstream(folder / "level.geojson")
      << collection({R"({"type":"Feature","id":"L0","feature_type":"level","properties":)"
                     R"({"category":"unspecified","ordinal":0,"name":{"en":"Ground"},)"
                     R"("short_name":{"en":"G"}},"geometry":{"type":"Polygon","coordinates":)" +
                     box(0, -5, 20, 7) + "}}"});
  std::ofstream(folder / "unit.geojson") << collection(
      {unit("hall", "walkway", box(0, 0, 20, 2.4)), unit("north-a", "office", box(0, 2.4, 10, 7)),
       unit("north-b", "room", box(10, 2.4, 20, 7)), unit("south", "classroom", box(0, -5, 20, 0)),
       unit("core", "stairs", box(20, 0, 22, 2.4))});
  std::ofstream(folder / "opening.geojson")
      << collection({opening(4, 2.4, 5, 2.4), opening(14, 2.4, 15, 2.4), opening(9, 0, 10, 0)});
  return folder;
}

TEST(PlanImport, ImdfFolderImportsUnitsAndOpenings) {
  const fs::path folder = write_imdf(test::scratch_folder() / "imdf");
  const floorplan::ImportedPlan plan = floorplan::import_plan(folder, {});
  fs::remove_all(folder);
  EXPECT_EQ(plan.format, floorplan::PlanFormat::kImdf);
  EXPECT_EQ(plan.level, "G");
  EXPECT_EQ(plan.counts.corridors, 1);
  EXPECT_EQ(plan.counts.rooms, 3);
  EXPECT_EQ(plan.counts.skipped, 1) << "the stairs are no free space";
  EXPECT_EQ(plan.counts.doors, 3);
  EXPECT_EQ(plan.counts.space_doors, 3) << "every opening lies on a wall between two units";
  for (const sim::scene::SpaceDoor& d : plan.doors)
    EXPECT_NEAR((d.to_m - d.from_m).norm(), 1.0, 0.02);
  EXPECT_EQ(plan.spaces.size(), 4u);
  expect_route_revisits(floorplan::imported_scene(plan, {}));
}

// Without level.geojson, or with units on a level it does not list, the import said "no level
// with a walkway or lobby unit": the fault is named now.
TEST(PlanImport, ImdfUnitsWithoutTheirLevelNameWhatIsMissing) {
  const fs::path folder = write_imdf(test::scratch_folder() / "imdf_levels");
  const std::string level_file = (folder / "level.geojson").string();
  std::string levels;
  {
    std::ifstream in(level_file);
    levels.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  fs::remove(level_file);
  try {
    floorplan::import_plan(folder, {});
    ADD_FAILURE() << "no level.geojson was accepted";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(level_file + ": not found"), std::string::npos)
        << e.what();
  }
  std::ofstream(level_file) << levels.replace(levels.find("\"L0\""), 4, "\"L9\"");
  try {
    floorplan::import_plan(folder, {});
    ADD_FAILURE() << "units on an unlisted level were accepted";
  } catch (const ParseError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("unit.geojson"), std::string::npos) << what;
    EXPECT_NE(what.find("'L0' is not a level of level.geojson (its level ids: L9)"),
              std::string::npos)
        << what;
  }
  fs::remove_all(folder);
}

TEST(PlanImport, UserRouteWaypointOutsideThePlanIsAnErrorNotDropped) {
  const fs::path folder = write_imdf(test::scratch_folder() / "imdf");
  const floorplan::ImportedPlan plan = floorplan::import_plan(folder, {});
  fs::remove_all(folder);
  floorplan::SceneOptions options;
  // Both points lie in the plan's local frame; the second is kilometres outside the building.
  Eigen::Vector2d inside = Eigen::Vector2d::Zero();  // the walkway's centre
  for (const sim::scene::Space& space : plan.spaces)
    if (space.kind == sim::scene::SpaceKind::kCorridor) {
      for (const Eigen::Vector2d& p : space.polygon_m) inside += p;
      inside /= static_cast<double>(space.polygon_m.size());
    }
  options.route_m = {inside, Eigen::Vector2d(1000.0, 1000.0)};
  try {
    floorplan::imported_scene(plan, options);
    ADD_FAILURE() << "a waypoint 1 km outside the plan was accepted";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("route waypoint 2 (1000.00, 1000.00)"), std::string::npos)
        << e.what();
  }
}

/// A comb: one main corridor 2.5 m wide along x, `branches` corridors 2 m wide and 200 m long
/// off it every 12 m, and rooms on both sides of each branch every 4 m, drawn 0.2 m apart (the
/// walls left out, as OSM drawings often do), as OSM Simple Indoor Tagging GeoJSON near lon/lat
/// (0, 0). Returns the file.
fs::path write_comb(const fs::path& file, int branches) {
  const double deg = 1 / 111320.0;
  std::vector<std::string> features;
  auto poly = [&](double x0, double y0, double x1, double y1, const char* indoor) {
    features.push_back(fmt::format(
        R"({{"type":"Feature","properties":{{"@id":"way/{}","indoor":"{}","level":"1"}},)"
        R"("geometry":{{"type":"Polygon","coordinates":[[[{},{}],[{},{}],[{},{}],[{},{}],[{},{}]]]}}}})",
        features.size() + 1, indoor, x0 * deg, y0 * deg, x1 * deg, y0 * deg, x1 * deg, y1 * deg,
        x0 * deg, y1 * deg, x0 * deg, y0 * deg));
  };
  poly(0, 0, branches * 12.0, 2.5, "corridor");
  for (int b = 0; b < branches; ++b) {
    const double x = b * 12.0 + 4.0;
    poly(x, 2.5, x + 2.0, 202.5, "corridor");
    for (int j = 0; j < 50; ++j) {
      poly(x - 3.9, 2.6 + 4.0 * j, x - 0.1, 6.4 + 4.0 * j, "room");
      poly(x + 2.1, 2.6 + 4.0 * j, x + 5.9, 6.4 + 4.0 * j, "room");
    }
  }
  std::ofstream(file) << R"({"type":"FeatureCollection","features":[)"
                      << fmt::format("{}", fmt::join(features, ",")) << "]}";
  return file;
}

// 1 000 rooms on 2 km of corridor: more spaces than step 2 grows into one unclaimed geometry
// (space_partition.cpp, grow_into_tiles), and past the budget for exact walk costs between every
// two of the tour's targets, so the tour is planned on the graph of neighbouring targets
// (route_planner.cpp, SparseWalks). Every room must still be a space, the gaps closed into walls,
// and the tour must reach the far end of every branch (one that skipped a branch would pass 200 m
// from its end) and go round its loop twice.
TEST(PlanImport, AThousandRoomCombGetsATourThatReachesTheEndOfEveryBranch) {
  const int branches = 10;
  const fs::path file = write_comb(test::scratch_folder() / "comb.geojson", branches);
  const floorplan::ImportedPlan plan = floorplan::import_plan(file, {});
  fs::remove(file);
  EXPECT_EQ(plan.counts.rooms, 50 * 2 * branches);
  EXPECT_GE(plan.spaces.size(), 50u * 2 * branches) << "every room is a space";
  EXPECT_GE(plan.counts.space_doors, 50 * 2 * branches) << "every room has a door";
  floorplan::SceneOptions options;
  options.access_points = 10;
  const sim::scene::Scene scene = floorplan::imported_scene(plan, options);
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300);
  for (const sim::scene::Space& space : plan.spaces)
    for (const Eigen::Vector2d& p : space.polygon_m) lo = lo.cwiseMin(p);
  for (int b = 0; b < branches; ++b) {
    const Eigen::Vector2d end = lo + Eigen::Vector2d(b * 12.0 + 5.0, 201.0);
    double nearest_m = 1e300;
    for (const Eigen::Vector2d& w : scene.route.waypoints_m)
      nearest_m = std::min(nearest_m, (w - end).norm());
    EXPECT_LT(nearest_m, 9.0) << "branch " << b << ": every cell is within 8 m of a target";
  }
  expect_route_revisits(scene);
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
