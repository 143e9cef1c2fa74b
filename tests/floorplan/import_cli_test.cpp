// `wifislam import` refuses bad plans with a located message, exit 2 and nothing written: a ring
// that crosses itself, a level the plan does not have, a file GDAL cannot read, a plan with no
// usable polygon; and it never writes the scene over a file it read.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "tests/floorplan/shipped_plans.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;

std::string feature(const std::string& indoor, const std::string& ring) {
  return R"({"type":"Feature","properties":{"@id":"way/7","indoor":")" + indoor +
         R"(","level":"1"},"geometry":{"type":"Polygon","coordinates":[)" + ring + "]}}";
}

std::string collection(const std::vector<std::string>& features) {
  std::string out = R"({"type":"FeatureCollection","features":[)";
  for (std::size_t i = 0; i < features.size(); ++i) out += (i ? "," : "") + features[i];
  return out + "]}";
}

class ImportCli : public ::testing::Test {
 protected:
  void SetUp() override { scratch_ = test::scratch_folder(); }
  void TearDown() override { fs::remove_all(scratch_); }
  void expect_refused(const std::string& args, const std::vector<std::string>& parts) {
    const test::CliResult r =
        test::run_wifislam(args + " -o " + (scratch_ / "out.yaml").string(), scratch_);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    for (const std::string& part : parts) EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(scratch_ / "out.yaml"));
  }
  fs::path scratch_;
};

TEST_F(ImportCli, SelfIntersectingRingIsRefusedAtItsFeature) {
  // A bow tie: the ring crosses itself.
  const std::string bow_tie =
      "[[-96.9272,19.5413],[-96.9270,19.5415],[-96.9270,19.5413],[-96.9272,19.5415],"
      "[-96.9272,19.5413]]";
  test::write_file(scratch_ / "bad.geojson", collection({feature("corridor", bow_tie)}));
  expect_refused("import " + (scratch_ / "bad.geojson").string(),
                 {"bad.geojson: feature 0 (way/7)", "not a valid polygon", "Self-intersection"});
}

TEST_F(ImportCli, MissingLevelNamesTheLevelsThereAre) {
  expect_refused(
      "import " +
          (test::kShippedPlans / "fei_uv_xalapa_osm_sit" / "fei_levels_1_2.geojson").string() +
          " --level 7",
      {"no level '7'", "its levels: 1, 2"});
  expect_refused(
      "import " +
          (test::kShippedPlans / "westport_house_wrld" / "westport-house-floor-2.geojson")
              .string() +
          " --level 9",
      {"no level '9'", "G, 1, 2, 3, 4, 5, 6"});
}

TEST_F(ImportCli, UnreadableFileIsRefusedNamingIt) {
  test::write_file(scratch_ / "garbage.geojson", "this is not { a plan");
  expect_refused("import " + (scratch_ / "garbage.geojson").string(),
                 {"garbage.geojson", "GDAL cannot read it"});
}

TEST_F(ImportCli, PlanWithoutUsablePolygonIsRefused) {
  const std::string square =
      "[[-96.9272,19.5413],[-96.9270,19.5413],[-96.9270,19.5415],[-96.9272,19.5415],"
      "[-96.9272,19.5413]]";
  // Only a room: no corridor or area, so no level with walkable space.
  test::write_file(scratch_ / "rooms.geojson", collection({feature("room", square)}));
  expect_refused("import " + (scratch_ / "rooms.geojson").string(),
                 {"rooms.geojson", "no indoor=corridor or indoor=area"});
}

// A corridor whose coordinates are text reads as no polygon; the import said the plan had no
// corridor at all. It names the feature.
TEST_F(ImportCli, ACorridorWhoseGeometryDoesNotReadIsNamed) {
  const std::string text_ring =
      R"([["-96.9272","19.5413"],["-96.9270","19.5413"],["-96.9270","19.5415"],)"
      R"(["-96.9272","19.5413"]])";
  test::write_file(scratch_ / "text.geojson", collection({feature("corridor", text_ring)}));
  expect_refused("import " + (scratch_ / "text.geojson").string(),
                 {"text.geojson", "indoor=corridor has no polygon that reads as one"});
}

TEST_F(ImportCli, NoFileTheImportReadsIsWrittenOver) {
  // main.json, the level's paths file and ATTRIBUTION.md are read beside the plan, not named on
  // the command line: the scene must not replace any of them.
  const fs::path plan = scratch_ / "wrld";
  fs::copy(test::kShippedPlans / "westport_house_wrld", plan);
  for (const char* side_input :
       {"main.json", "westport-house-floor-2-paths.geojson", "ATTRIBUTION.md"}) {
    const std::string before = test::read_file(plan / side_input);
    const test::CliResult r =
        test::run_wifislam("import " + (plan / "westport-house-floor-2.geojson").string() + " -o " +
                               (plan / side_input).string(),
                           scratch_);
    EXPECT_EQ(r.exit_code, 2) << side_input << ": " << r.err;
    EXPECT_NE(r.err.find("is an input of this command"), std::string::npos) << r.err;
    EXPECT_EQ(test::read_file(plan / side_input), before) << side_input;
  }
}

TEST_F(ImportCli, BrokenMainJsonIsLocatedNotAnInternalError) {
  const fs::path plan = scratch_ / "wrld";
  fs::copy(test::kShippedPlans / "westport_house_wrld", plan);
  const std::string level = (plan / "westport-house-floor-2.geojson").string();
  std::string main_json = test::read_file(plan / "main.json");
  const std::size_t name = main_json.find("\"name\": \"G\"");
  ASSERT_NE(name, std::string::npos);
  test::write_file(plan / "main.json", main_json.replace(name, 11, "\"name\": 5"));
  expect_refused("import " + level, {"main.json", "levels[0]", "must be strings"});
  fs::remove(plan / "main.json");
  fs::create_directory(plan / "main.json");
  expect_refused("import " + level, {"main.json", "is not a regular file"});
}

// The building's outline file lies beside main.json but is none of its levels: it imported as
// one empty hall (no walls, one space).
TEST_F(ImportCli, AFileBesideMainJsonThatIsNoLevelIsRefused) {
  const fs::path outline =
      test::kShippedPlans / "westport_house_wrld" / "westport-house-outline.geojson";
  ASSERT_TRUE(fs::exists(outline));
  expect_refused("import " + outline.string(),
                 {"westport-house-outline.geojson", "not one of the levels main.json"});
}

// The building's point places the plan on Earth; a malformed one fell back to the plan's centre
// without a word. Each is refused naming the key (the import fails before planning the route).
TEST_F(ImportCli, AMalformedBuildingLocationIsRefusedNotReplaced) {
  const fs::path plan = scratch_ / "wrld";
  fs::copy(test::kShippedPlans / "westport_house_wrld", plan);
  const std::string level = (plan / "westport-house-floor-gf.geojson").string();
  const std::string main_json = test::read_file(plan / "main.json");
  const std::size_t at = main_json.find("\"coordinates\"");
  ASSERT_NE(at, std::string::npos) << main_json.substr(0, 400);
  const std::size_t end = main_json.find(']', at) + 1;
  for (const std::string bad : {"\"coordinates\": [\"a\", \"b\"]", "\"coordinates\": [500, 56.4]",
                                "\"coordinates\": [-2.97]", "\"place\": \"Dundee\""}) {
    std::string edited = main_json;
    test::write_file(plan / "main.json", edited.replace(at, end - at, bad));
    expect_refused("import " + level, {"main.json", "location.coordinates"});
  }
}

// --name becomes the scene's name, which names folders: checked before any work, naming --name.
TEST_F(ImportCli, ANameThatCannotNameAFolderIsRefusedAsTheOption) {
  const std::string level =
      (test::kShippedPlans / "westport_house_wrld" / "westport-house-floor-gf.geojson").string();
  for (const std::string bad : {"'x y: z'", "../up", "a/b"})
    expect_refused("import " + level + " --name " + bad, {"--name", "not a scene name"});
}

TEST_F(ImportCli, AFeatureFarFromTheRestIsRefusedBeforeTheSceneIsBuilt) {
  // A corridor and one room half a degree (~50 km) away: the scene could not hold it, and
  // building it first took minutes and gigabytes.
  const std::string corridor =
      "[[-96.9272,19.5413],[-96.9262,19.5413],[-96.9262,19.54133],[-96.9272,19.54133],"
      "[-96.9272,19.5413]]";
  const std::string far_room =
      "[[-96.4272,19.5413],[-96.4270,19.5413],[-96.4270,19.5415],[-96.4272,19.5415],"
      "[-96.4272,19.5413]]";
  test::write_file(scratch_ / "stray.geojson",
                   collection({feature("corridor", corridor), feature("room", far_room)}));
  const auto t0 = std::chrono::steady_clock::now();
  expect_refused("import " + (scratch_ / "stray.geojson").string(),
                 {"stray.geojson", "from the plan's centre", "a scene keeps within 10000 m"});
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 20.0);
}

TEST_F(ImportCli, OsmXmlIsReadThroughGdalsOsmDriver) {
  // A corridor (20 x 2.4 m) and a room beside it, as closed ways of an .osm file, near
  // (lon 10, lat 45). (GDAL's OSM driver takes a node at exactly (0, 0) for a missing one.)
  auto node = [](int id, double x_m, double y_m) {
    return fmt::format(R"(<node id="{}" version="1" lat="{:.8f}" lon="{:.8f}"/>)", id,
                       45.0 + y_m / 111132.0, 10.0 + x_m / (111320.0 * std::cos(M_PI / 4)));
  };
  auto way = [](int id, int first, const std::string& indoor) {
    std::string w = fmt::format(R"(<way id="{}" version="1">)", id);
    for (int k : {0, 1, 2, 3, 0}) w += fmt::format(R"(<nd ref="{}"/>)", first + k);
    return w + fmt::format(R"(<tag k="indoor" v="{}"/><tag k="level" v="0"/></way>)", indoor);
  };
  std::string osm = R"(<?xml version="1.0" encoding="UTF-8"?><osm version="0.6" generator="test">)";
  osm += node(1, 0, 0) + node(2, 20, 0) + node(3, 20, 2.4) + node(4, 0, 2.4);
  osm += node(5, 0, 2.4) + node(6, 8, 2.4) + node(7, 8, 7) + node(8, 0, 7);
  osm += way(100, 1, "corridor") + way(101, 5, "room") + "</osm>";
  // `text` written as <name>.osm and imported into <name>.yaml.
  const auto import_osm = [&](const std::string& name, const std::string& text) {
    test::write_file(scratch_ / (name + ".osm"), text);
    return test::run_wifislam("import " + (scratch_ / (name + ".osm")).string() + " -o " +
                                  (scratch_ / (name + ".yaml")).string(),
                              scratch_);
  };
  const auto expect_the_plan = [](const test::CliResult& r) {
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("read: 1 rooms, 1 corridors, 0 areas"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("2 spaces, 1 doors"), std::string::npos) << r.out;
  };
  expect_the_plan(import_osm("plan", osm));

  // The file is one line: its nodes are checked too. A latitude that is no number was read by
  // GDAL as 0 (the pre-check looked only at elements that start a line).
  std::string bad = osm;
  const std::string lat = R"(lat=")";
  bad.insert(bad.find(lat, bad.find(R"(<node id="3")")) + lat.size(), "x");
  const test::CliResult refused = import_osm("bad", bad);
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("bad.osm:1 (node/3)"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("expected a number of degrees"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(scratch_ / "bad.yaml"));
  // An element per line, spaces around each latitude: read as GDAL reads them, the same import
  // (" 45.0" was refused). A comment naming a node the file lacks is no way of the plan.
  std::string padded = osm;
  for (std::size_t at = padded.find("/>"); at != std::string::npos; at = padded.find("/>", at + 3))
    padded.insert(at + 2, "\n");
  for (std::size_t at = padded.find(lat); at != std::string::npos;
       at = padded.find(lat, at + lat.size() + 1))
    padded.insert(at + lat.size(), " ");
  padded.insert(padded.find("</osm>"), R"(<!-- <way id="9"><nd ref="999"/></way> -->)");
  expect_the_plan(import_osm("padded", padded));
  // An encoding GDAL adds to expat's own: windows-1252, with a name in it ("Caf\xe9 \x80").
  std::string windows_1252 = osm;
  windows_1252.replace(windows_1252.find("UTF-8"), 5, "windows-1252");
  windows_1252.insert(windows_1252.find(R"(<tag k="indoor" v="room"/>)"),
                      "<tag k=\"name\" v=\"Caf\xe9 \x80\"/>");
  expect_the_plan(import_osm("windows_1252", windows_1252));
  // A node after the way that names it: GDAL's driver, reading in order, dropped the point.
  std::string late = osm;
  const std::string node_3 =
      late.substr(late.find(R"(<node id="3")"),
                  late.find("/>", late.find(R"(<node id="3")")) + 2 - late.find(R"(<node id="3")"));
  late.erase(late.find(node_3), node_3.size());
  late.insert(late.find("</osm>"), node_3);
  const test::CliResult after = import_osm("late", late);
  EXPECT_EQ(after.exit_code, 2) << after.err;
  EXPECT_NE(after.err.find("late.osm:1 (way/100)"), std::string::npos) << after.err;
  EXPECT_NE(after.err.find("node 3 comes after this way"), std::string::npos) << after.err;
  // XML GDAL cannot read is refused where it stops being XML.
  const test::CliResult broken = import_osm("broken", osm.substr(0, osm.find("<way")) + "<way id=");
  EXPECT_EQ(broken.exit_code, 2) << broken.err;
  EXPECT_NE(broken.err.find("broken.osm:1:"), std::string::npos) << broken.err;
  EXPECT_NE(broken.err.find("XML that GDAL's OSM driver cannot read"), std::string::npos)
      << broken.err;
}

TEST_F(ImportCli, ImportedSceneGeneratesADataset) {
  const fs::path scene = scratch_ / "fei.yaml";
  const test::CliResult imported = test::run_wifislam(
      "import " +
          (test::kShippedPlans / "fei_uv_xalapa_osm_sit" / "fei_levels_1_2.geojson").string() +
          " --level 2 -o " + scene.string(),
      scratch_);
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  EXPECT_NE(test::read_file(scene).find("OpenStreetMap contributors"), std::string::npos)
      << "the ODbL attribution travels with the scene";
  const test::CliResult generated =
      test::run_wifislam("generate " + scene.string() + " -o " + (scratch_ / "ds").string() +
                             " --fps 1 --max-frames 6 --threads 2 -q",
                         scratch_);
  ASSERT_EQ(generated.exit_code, 0) << generated.err;
  EXPECT_TRUE(fs::exists(scratch_ / "ds" / "groundtruth.txt"));
  EXPECT_TRUE(fs::exists(scratch_ / "ds" / "wifi.csv"));
}

// Issue 46: a whole building. Both FEI levels in one scene, stacked at the stated default, the
// route on the level asked for; its world has both storeys, its radio hears both levels' APs,
// and it generates a dataset.
TEST_F(ImportCli, AllLevelsImportIntoOneBuildingThatGeneratesADataset) {
  const fs::path scene = scratch_ / "fei_building.yaml";
  const test::CliResult imported = test::run_wifislam(
      "import " +
          (test::kShippedPlans / "fei_uv_xalapa_osm_sit" / "fei_levels_1_2.geojson").string() +
          " --all-levels --level 2 --access-points 5 -o " + scene.string(),
      scratch_);
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  EXPECT_NE(imported.out.find("levels 1, 2 stacked 3.1 m apart"), std::string::npos)
      << imported.out;
  const std::string text = test::read_file(scene);
  EXPECT_NE(text.find("OpenStreetMap contributors"), std::string::npos);
  EXPECT_NE(text.find("elevation_m: 3.1"), std::string::npos) << "the default is written";
  const test::CliResult world = test::run_wifislam("world " + scene.string(), scratch_);
  ASSERT_EQ(world.exit_code, 0) << world.err;
  EXPECT_NE(world.out.find("levels: 1 at 0 m, 2 at 3.1 m (route)"), std::string::npos) << world.out;
  EXPECT_NE(world.out.find("access points: 10"), std::string::npos) << world.out;
  const test::CliResult generated =
      test::run_wifislam("generate " + scene.string() + " -o " + (scratch_ / "ds").string() +
                             " --fps 1 --max-frames 4 --threads 2 -q",
                         scratch_);
  ASSERT_EQ(generated.exit_code, 0) << generated.err;
  EXPECT_TRUE(fs::exists(scratch_ / "ds" / "wifi.csv"));
  // A level the picture is asked for that the building lacks: exit 2, nothing drawn.
  const test::CliResult bad = test::run_wifislam(
      "world " + scene.string() + " --level 3 --plan " + (scratch_ / "l3.png").string(), scratch_);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--level 3: the scene has no such level (levels: 1, 2)"),
            std::string::npos)
      << bad.err;
  EXPECT_FALSE(fs::exists(scratch_ / "l3.png"));
}

// Issue 44: coordinates that are no longitude and latitude reached PROJ and GDAL (an unlocated
// "ERROR 1", a 300-digit projection string); a way naming a node the file lacks was imported as
// a smaller polygon; /dev/zero was "no such plan file" (exit 3).
TEST_F(ImportCli, PlansThatAreNotWhatTheySayAreLocatedErrors) {
  for (const std::string& point :
       {std::string("[1e308, 0]"), std::string("[200, 0]"), std::string("[0, 95]")}) {
    const std::string ring = "[[0, 0], " + point + ", [0.0002, 0.0001], [0, 0.0001], [0, 0]]";
    test::write_file(scratch_ / "far.geojson", collection({feature("corridor", ring)}));
    expect_refused("import " + (scratch_ / "far.geojson").string(),
                   {"far.geojson: feature 0 (way/7)", "coordinates", "longitude"});
  }
  test::write_file(scratch_ / "missing.osm",
                   "<?xml version='1.0' encoding='UTF-8'?>\n<osm version=\"0.6\">\n"
                   "  <node id=\"1\" lat=\"0.0\" lon=\"0.0\"/>\n"
                   "  <node id=\"2\" lat=\"0.0\" lon=\"0.0002\"/>\n"
                   "  <node id=\"3\" lat=\"0.0001\" lon=\"0.0002\"/>\n"
                   "  <way id=\"10\">\n    <nd ref=\"1\"/>\n    <nd ref=\"2\"/>\n"
                   "    <nd ref=\"3\"/>\n    <nd ref=\"4\"/>\n    <nd ref=\"1\"/>\n"
                   "    <tag k=\"indoor\" v=\"corridor\"/>\n    <tag k=\"level\" v=\"0\"/>\n"
                   "  </way>\n</osm>\n");
  expect_refused("import " + (scratch_ / "missing.osm").string(),
                 {"missing.osm:10 (way/10)", "node 4 is not in the file"});
  // GDAL's OSM driver reads a latitude that is no number as 0: the import failed later with
  // "walkable space too small", naming neither the node nor the attribute.
  std::string bad_lat = test::read_file(scratch_ / "missing.osm");
  const std::string good_lat = "lat=\"0.0001\"";
  bad_lat.replace(bad_lat.find(good_lat), good_lat.size(), "lat=\"abc\"");
  test::write_file(scratch_ / "bad_lat.osm", bad_lat);
  expect_refused("import " + (scratch_ / "bad_lat.osm").string(),
                 {"bad_lat.osm:5 (node/3)", "lat", "'abc'", "expected a number of degrees"});
  test::write_file(scratch_ / "far_lon.osm",
                   "<osm version=\"0.6\">\n<node id=\"9\" lat=\"1\" lon=\"200\"/>\n</osm>\n");
  expect_refused("import " + (scratch_ / "far_lon.osm").string(),
                 {"far_lon.osm:2 (node/9)", "lon", "'200'"});
  expect_refused("import /dev/zero", {"/dev/zero", "not a plan file"});
}

}  // namespace
}  // namespace wifislam
