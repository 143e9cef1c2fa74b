// `wifislam localize` as a user runs it: on the aliasing ladder, Wi-Fi words appended to the
// visual ones raise FAB-MAP's share of queries matched within 2 m (the thermometer code, whose
// 23 words an access point outweigh the presence bit; the presence code's gain is smaller, see
// docs/fabmap/README.md); a dataset without Wi-Fi scans is refused for the Wi-Fi methods (exit 2,
// naming its wifi.csv, nothing written) and served for visual FAB-MAP.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"
#include "tests/support/upstairs_scene.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;
using test::read_file;

/// summary.json's share of queries within 2 m, per method.
double share_within_2m(const nlohmann::json& summary, const std::string& method) {
  for (const auto& m : summary.at("methods")) {
    if (m.at("method") == method) return m.at("all").at("within_2m").get<double>();
  }
  ADD_FAILURE() << "no method " << method;
  return -1.0;
}

TEST(LocalizeCli, WifiWordsRaiseFabmapsShareWithin2mOnTheAliasingLadder) {
  const fs::path scratch = test::scratch_folder();
  const test::CliResult r =
      test::run_wifislam(std::string("localize ") + WIFISLAM_SCENES_DIR +
                             "/aliasing_ladder.yaml --method "
                             "fabmap,wifi-fabmap --wifi-words thermometer -q -o " +
                             (scratch / "out").string(),
                         scratch);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json summary =
      nlohmann::json::parse(test::read_file(scratch / "out" / "summary.json"));
  EXPECT_GT(summary.at("query_images").get<int>(), 50);
  const double visual = share_within_2m(summary, "fabmap");
  const double wifi = share_within_2m(summary, "wifi-fabmap");
  EXPECT_GT(wifi, visual) << "fabmap " << visual << ", wifi-fabmap " << wifi;
  for (const char* file :
       {"queries.csv", "cdf.csv", "cdf.png", "cdf.svg", "pr.csv", "summary.md"}) {
    EXPECT_TRUE(fs::exists(scratch / "out" / file)) << file;
  }
  fs::remove_all(scratch);
}

TEST(LocalizeCli, ADatasetWithoutWifiIsRefusedForTheWifiMethods) {
  const fs::path scratch = test::scratch_folder();
  // The tiny loop pauses 1 s, shorter than a scan: its wifi.csv has no scan.
  test::write_file(scratch / "tiny.yaml", test::kTinyLoopYaml);
  const std::string generate = std::string(WIFISLAM_BINARY) + " generate " +
                               (scratch / "tiny.yaml").string() + " --fps 2 -q -o " +
                               (scratch / "dataset").string();
  ASSERT_EQ(std::system(generate.c_str()), 0);
  const std::string input = (scratch / "dataset").string();
  for (const char* method : {"wifi-fabmap", "wifi-clusters"}) {
    const test::CliResult r = test::run_wifislam(
        "localize " + input + " --method " + method + " -o " + (scratch / "out").string(), scratch);
    test::expect_located_bad_input(r, (scratch / "dataset" / "wifi.csv").string(), method);
    EXPECT_FALSE(fs::exists(scratch / "out"));
    EXPECT_FALSE(fs::exists(scratch / "out.partial"));
  }
  const test::CliResult visual = test::run_wifislam(
      "localize " + input + " --method fabmap -q -o " + (scratch / "out").string(), scratch);
  EXPECT_EQ(visual.exit_code, 0) << visual.err;
  EXPECT_TRUE(fs::exists(scratch / "out" / "summary.json"));
  fs::remove_all(scratch);
}

// Issue 44: localize refused the tool's own 1 fps dataset ("no pose within 0.1 s": its scans fall
// between the poses, which it now interpolates, as eval does); its message suggested --no-verify,
// which it did not take; an empty --route and a trailing comma in --method were accepted.
TEST(LocalizeCli, AOneFpsDatasetLocalisesAndEmptyListsAreRefused) {
  const fs::path scratch = test::scratch_folder();
  const fs::path scene =
      test::tiny_loop_with(scratch, "duration_s: 1.0", "duration_s: 4.0", "tiny.yaml");
  const std::string generate = std::string(WIFISLAM_BINARY) + " generate " + scene.string() +
                               " --fps 1 -q -o " + (scratch / "dataset").string();
  ASSERT_EQ(std::system(generate.c_str()), 0);
  const std::string input = (scratch / "dataset").string();
  test::CliResult r = test::run_wifislam(
      "localize " + input + " --no-verify -q -o " + (scratch / "out").string(), scratch);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(scratch / "out" / "summary.json"));
  for (const std::string& bad : {std::string("--method fabmap,"), std::string("--method ,fabmap"),
                                 std::string("--route \"\""), std::string("--route A,,B")}) {
    r = test::run_wifislam(
        "localize " + scene.string() + " " + bad + " -o " + (scratch / "bad").string(), scratch);
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.err;
    EXPECT_FALSE(fs::exists(scratch / "bad")) << bad;
  }
  fs::remove_all(scratch);
}

// Issue 46: another floor of the same building in the map. The two storeys of
// two_storey_office look alike (one corridor, one appearance seed), so visual FAB-MAP often takes
// the place upstairs; our Wi-Fi clusters, whose candidates are the map places of similar
// signatures, hear that the APs of the query's floor are the strong ones and choose it more often.
TEST(LocalizeCli, AnotherFloorInTheMapIsTheWrongFloorAndWifiClustersChooseItLess) {
  const fs::path scratch = test::scratch_folder();
  const std::string ground = std::string(WIFISLAM_SCENES_DIR) + "/two_storey_office.yaml";
  test::write_upstairs_two_storey_office(scratch);
  // There and back on the ground floor: the way back revisits the map's first 40 %.
  const test::CliResult r = test::run_wifislam(
      "localize " + ground + " --route A,B,A --other-floor " +
          (scratch / "upstairs.yaml").string() + " -q -o " + (scratch / "out").string(),
      scratch);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json summary =
      nlohmann::json::parse(test::read_file(scratch / "out" / "summary.json"));
  const int upstairs_images = summary.at("other_floor_images").get<int>();
  EXPECT_GT(upstairs_images, 30);
  EXPECT_GT(summary.at("map_images").get<int>(), upstairs_images);
  std::map<std::string, double> wrong_floor;
  for (const auto& m : summary.at("methods"))
    wrong_floor[m.at("method").get<std::string>()] = m.at("wrong_floor").get<double>();
  ASSERT_EQ(wrong_floor.size(), 3u);
  EXPECT_GT(wrong_floor["fabmap"], 0.15) << "the floors look alike";
  EXPECT_LT(wrong_floor["wifi-clusters"], 0.5 * wrong_floor["fabmap"]);
  // queries.csv says which queries chose upstairs; their shares agree with the summary's.
  const std::string queries = read_file(scratch / "out" / "queries.csv");
  EXPECT_NE(queries.find(",time_s,wrong_floor\n"), std::string::npos);
  int fabmap_rows = 0, fabmap_wrong = 0;
  for (std::size_t at = queries.find('\n') + 1; at < queries.size();) {
    const std::size_t end = queries.find('\n', at);
    const std::string row = queries.substr(at, end - at);
    if (row.rfind("fabmap,", 0) == 0) ++fabmap_rows, fabmap_wrong += row.back() == '1';
    at = end + 1;
  }
  ASSERT_GT(fabmap_rows, 0);
  EXPECT_NEAR(static_cast<double>(fabmap_wrong) / fabmap_rows, wrong_floor["fabmap"], 1e-9);

  // The same level twice, and a building of one level, are refused before anything is written
  // (and before either route is rendered: the levels are the scenes').
  for (const std::string& other : {ground, std::string(WIFISLAM_SCENES_DIR) + "/c_hall.yaml"}) {
    const test::CliResult refused = test::run_wifislam(
        "localize " + ground + " --other-floor " + other + " -q -o " + (scratch / "no").string(),
        scratch);
    EXPECT_EQ(refused.exit_code, 2) << refused.err;
    EXPECT_NE(refused.err.find("--other-floor " + other), std::string::npos) << refused.err;
    EXPECT_FALSE(fs::exists(scratch / "no"));
  }
  // Queries on another level than the map's are not another visit of its route: refused too.
  const test::CliResult other_level = test::run_wifislam("localize " + ground + " --queries " +
                                                             (scratch / "upstairs.yaml").string() +
                                                             " -q -o " + (scratch / "no").string(),
                                                         scratch);
  EXPECT_EQ(other_level.exit_code, 2) << other_level.err;
  EXPECT_NE(other_level.err.find("its route is on level 'first', the map's on level 'ground'"),
            std::string::npos)
      << other_level.err;
  EXPECT_FALSE(fs::exists(scratch / "no"));
  fs::remove_all(scratch);
}

// The map from one run and the queries from another of the same route: a later session of the
// scene (its own pauses and Wi-Fi draws), read by another device, or a dataset generated as one.
TEST(LocalizeCli, QueriesFromAnotherSessionOrDatasetAreMatchedToTheWholeFirstRun) {
  const fs::path scratch = test::scratch_folder();
  const std::string scene =
      test::tiny_loop_with(scratch, "duration_s: 1.0", "duration_s: 4.0", "tiny.yaml").string();
  const auto summary_of = [&](const std::string& out) {
    return nlohmann::json::parse(test::read_file(scratch / out / "summary.json"));
  };
  test::CliResult r = test::run_wifislam(
      "localize " + scene + " --queries-session 1 --queries-device weaker_phone -q -o " +
          (scratch / "session").string(),
      scratch);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json s = summary_of("session");
  EXPECT_TRUE(s.at("queries_from_another_run").get<bool>());
  EXPECT_FALSE(s.contains("map_share"));
  const int map_images = s.at("map_images").get<int>(), queries = s.at("query_images").get<int>();
  EXPECT_GT(map_images, 15);
  EXPECT_NEAR(queries, map_images, 0.2 * map_images);  // one lap each
  EXPECT_NE(read_file(scratch / "session" / "summary.md").find("another run of its route"),
            std::string::npos);

  // The same as a dataset of session 1, given with --queries.
  const std::string generate = std::string(WIFISLAM_BINARY) + " generate " + scene +
                               " --session 1 --fps 2 -q -o " + (scratch / "s1").string();
  ASSERT_EQ(std::system(generate.c_str()), 0);
  r = test::run_wifislam("localize " + scene + " --queries " + (scratch / "s1").string() +
                             " --no-verify -q -o " + (scratch / "dataset").string(),
                         scratch);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(summary_of("dataset").at("map_images").get<int>(), map_images);

  // Options that do not go together, and a run of another route, are refused: exit 2, nothing
  // written.
  // The same loop 40 m east: another route (another building, too).
  std::string far = test::kTinyLoopYaml;
  for (const auto& [from, to] : {std::pair{"[0, 0]", "[40, 0]"}, std::pair{"[7, 0]", "[47, 0]"},
                                 std::pair{"[7, 5]", "[47, 5]"}, std::pair{"[0, 5]", "[40, 5]"}})
    far.replace(far.find(from), std::string(from).size(), to);
  far.replace(far.find("duration_s: 1.0"), 15, "duration_s: 4.0");
  test::write_file(scratch / "far.yaml", far);
  const std::string other_route = (scratch / "far.yaml").string();
  for (const std::string& bad :
       {std::string("--queries-session 1 --map-share 0.5"),
        std::string("--queries-device weaker_phone"),
        std::string("--queries-session 1 --queries ") + other_route,
        std::string("--queries ") + other_route,
        // The input as its own queries: every query would find itself in the map.
        std::string("--queries ") + scene,
        std::string("--queries-session 1 --queries-device no_such_phone")}) {
    r = test::run_wifislam("localize " + scene + " " + bad + " -q -o " + (scratch / "bad").string(),
                           scratch);
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.err;
    EXPECT_FALSE(fs::exists(scratch / "bad")) << bad;
  }
  r = test::run_wifislam("localize " + (scratch / "s1").string() + " --queries-session 2 -q -o " +
                             (scratch / "bad").string(),
                         scratch);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  r = test::run_wifislam("localize " + (scratch / "s1").string() + " --queries " +
                             (scratch / "s1").string() + "/ --no-verify -q -o " +
                             (scratch / "bad").string(),
                         scratch);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("is the input itself"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(scratch / "bad"));
  // Another building whose route still runs within 2 m of the map's (its east side 0.5 m further
  // out) passed the route check: the buildings are compared first.
  std::string wider = test::tiny_wifi_loop_yaml();
  for (const auto& [from, to] : {std::pair{"[7, 0]", "[7.5, 0]"}, std::pair{"[7, 5]", "[7.5, 5]"}})
    wider.replace(wider.find(from), std::string(from).size(), to);
  test::write_file(scratch / "wider.yaml", wider);
  for (const std::string& queries : {scene, (scratch / "s1").string()}) {  // a scene, a dataset
    r = test::run_wifislam("localize " + (scratch / "wider.yaml").string() + " --queries " +
                               queries + " --no-verify -q -o " + (scratch / "bad").string(),
                           scratch);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("another building"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(scratch / "bad"));
  }
  fs::remove_all(scratch);
}

}  // namespace
}  // namespace wifislam
