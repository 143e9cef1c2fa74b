// `wifislam study plot` and `wifislam study place` through the command line: the curves are the
// database's medians over seeds, lines split by placement and variant; greedy placement tells the
// route's places apart better than random placement of as many access points, and the block it
// writes loads as a scene's access points; the shipped study files load and every case checks.
//
// study place's placement error: (1 - share of pause pairs under 4 m similar) + share over 12 m
// similar (study/greedy_placement.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <utility>

#include "core/median.hpp"
#include "radio_model/propagation_model.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/site/site.hpp"
#include "study/result_store.hpp"
#include "study/study_file.hpp"
#include "study/study_runner.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"
#include "tests/support/upstairs_scene.hpp"

namespace wifislam::study {
namespace {

namespace fs = std::filesystem;

const std::string kScenes = WIFISLAM_SCENES_DIR;

std::vector<std::vector<std::string>> read_csv(const fs::path& path) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(test::read_file(path));
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream cells_in(line);
    for (std::string cell; std::getline(cells_in, cell, ',');) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    rows.push_back(cells);
  }
  return rows;
}

bool is_png(const fs::path& path) {
  const std::string bytes = test::read_file(path);
  return bytes.size() > 1000 && bytes.compare(0, 4, "\x89PNG") == 0;
}

TEST(StudyPlot, CurvesAreTheDatabaseMediansOverSeedsWithALinePerPlacement) {
  const fs::path dir = test::scratch_folder();
  const fs::path file = dir / "placement.yaml";
  test::write_file(file, "version: 1\nname: plot_test\nscene: " + kScenes +
                             "/c_hall.yaml\nlevel: radio\n"
                             "set: {access_points.line_to_m: [20, 0]}\n"
                             "axes:\n  access_points.count: [10, 20]\n"
                             "  access_points.placement: [rooms, colinear]\n"
                             "  seed: [1, 2, 3]\n");
  const fs::path db = dir / "study.sqlite", plots = dir / "plots";
  ASSERT_EQ(test::run_wifislam("study run " + file.string() + " -q --jobs 2 -o " + db.string(), dir)
                .exit_code,
            0);
  const auto r = test::run_wifislam("study plot " + db.string() + " -o " + plots.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("x = access_points.count"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("lines by access_points.placement"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("pooled over seed"), std::string::npos) << r.out;
  for (const char* metric : {"resolution_m", "far_similar_share", "near_similar_share",
                             "aps_heard_per_pause", "clusters"}) {
    EXPECT_TRUE(is_png(plots / (std::string(metric) + ".png"))) << metric;
    EXPECT_NE(test::read_file(plots / (std::string(metric) + ".svg")).find("<svg"),
              std::string::npos);
  }

  // Every point of curves.csv is the median (and min, max) of its cases in the database.
  const ResultTable table = read_results(db);
  const int count_col = table.column("access_points_count");
  const int placement_col = table.column("access_points_placement");
  const int far_col = table.column("far_similar_share");
  ASSERT_GE(count_col, 0);
  ASSERT_GE(far_col, 0);
  int checked = 0;
  for (const auto& row : read_csv(plots / "curves.csv")) {
    if (row.size() != 7 || row[0] != "far_similar_share") continue;
    std::vector<double> values;
    for (const auto& db_row : table.rows) {
      const auto count = std::get<std::int64_t>(db_row[static_cast<std::size_t>(count_col)]);
      const auto placement = std::get<std::string>(db_row[static_cast<std::size_t>(placement_col)]);
      if (std::to_string(count) == row[2] && "placement " + placement == row[1])
        values.push_back(std::get<double>(db_row[static_cast<std::size_t>(far_col)]));
    }
    ASSERT_EQ(values.size(), 3u) << row[1] << " at " << row[2];
    EXPECT_EQ(row[3], "3");
    EXPECT_NEAR(std::stod(row[4]), median(values), 1e-5);
    EXPECT_NEAR(std::stod(row[5]), *std::min_element(values.begin(), values.end()), 1e-5);
    EXPECT_NEAR(std::stod(row[6]), *std::max_element(values.begin(), values.end()), 1e-5);
    ++checked;
  }
  EXPECT_EQ(checked, 4);  // 2 placements x 2 counts

  // The output folder is replaced only with --force; a file that is no study database is refused.
  EXPECT_EQ(
      test::run_wifislam("study plot " + db.string() + " -o " + plots.string(), dir).exit_code, 2);
  EXPECT_EQ(
      test::run_wifislam("study plot " + db.string() + " -o " + plots.string() + " --force", dir)
          .exit_code,
      0);
  test::write_file(dir / "notes.sqlite", "my notes");
  const auto foreign = test::run_wifislam(
      "study plot " + (dir / "notes.sqlite").string() + " -o " + (dir / "p2").string(), dir);
  EXPECT_EQ(foreign.exit_code, 2) << foreign.err;
  EXPECT_NE(foreign.err.find("not a study database"), std::string::npos) << foreign.err;
  EXPECT_FALSE(fs::exists(dir / "p2"));
  fs::remove_all(dir);
}

// A small aliasing study at SLAM level (the tiny loop, 2 fps, 10 s pauses so the Wi-Fi hears a
// pause): two rows per case, and the plot splits vanilla from Wi-Fi along the aliasing level.
TEST(StudyPlot, SlamLevelStudyHasAVanillaAndAWifiLinePerMetric) {
  const fs::path dir = test::scratch_folder();
  test::write_file(dir / "tiny.yaml", test::kTinyLoopYaml);
  const fs::path file = dir / "aliasing.yaml";
  test::write_file(file,
                   "version: 1\nname: aliasing_test\nscene: tiny.yaml\nlevel: slam\n"
                   "set: {route.pause.duration_s: 10}\n"
                   "axes:\n  appearance.aliasing: [0, 1]\n"
                   "slam: {fps: 2}\n");
  const fs::path db = dir / "study.sqlite", plots = dir / "plots";
  const auto run =
      test::run_wifislam("study run " + file.string() + " -q --jobs 2 -o " + db.string(), dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const ResultTable table = read_results(db);
  ASSERT_EQ(table.rows.size(), 4u);  // 2 cases x {vanilla, wifi}
  const int clusters = table.column("wifi_clusters");
  const int variant = table.column("variant");
  for (const auto& row : table.rows) {
    const auto v = std::get<std::string>(row[static_cast<std::size_t>(variant)]);
    const auto n = std::get<std::int64_t>(row[static_cast<std::size_t>(clusters)]);
    if (v == "wifi") {
      EXPECT_GT(n, 0) << "the Wi-Fi variant formed no cluster";
    } else {
      EXPECT_EQ(n, 0) << v;
    }
  }
  ASSERT_EQ(
      test::run_wifislam("study plot " + db.string() + " -o " + plots.string(), dir).exit_code, 0);
  EXPECT_TRUE(is_png(plots / "far_wrong_place_closures.png"));
  EXPECT_TRUE(is_png(plots / "ate_rmse_m.png"));
  std::set<std::string> lines;
  for (const auto& row : read_csv(plots / "curves.csv"))
    if (row.size() == 7 && row[0] == "ate_rmse_m") lines.insert(row[1] + "@" + row[2]);
  EXPECT_EQ(lines, (std::set<std::string>{"vanilla@0", "vanilla@1", "wifi@0", "wifi@1"}));
  fs::remove_all(dir);
}

TEST(StudyPlace, GreedyTellsPlacesApartBetterThanRandomAndItsBlockLoadsAsAScene) {
  const fs::path dir = test::scratch_folder();
  const fs::path out = dir / "place";
  const int budget = 8;
  const auto r =
      test::run_wifislam("study place " + kScenes + "/c_hall.yaml --budget " +
                             std::to_string(budget) + " --spacing 4 -q -o " + out.string(),
                         dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"placement.png", "error.png", "resolution.png"})
    EXPECT_TRUE(is_png(out / f)) << f;
  EXPECT_TRUE(fs::exists(out / "placement.svg"));
  const auto csv = read_csv(out / "placement.csv");
  ASSERT_EQ(csv.size(), static_cast<std::size_t>(budget + 1));
  // count,x_m,y_m,z_m,error,resolution_m,near,far,aps_heard,random_error,random_resolution_m,
  // random_near,random_far
  const auto& last = csv.back();
  ASSERT_EQ(last.size(), 13u);
  EXPECT_EQ(last[0], std::to_string(budget));
  // The error is what the header says it is, and greedy's is below random's at the budget.
  EXPECT_NEAR(std::stod(last[4]), 1.0 - std::stod(last[6]) + std::stod(last[7]), 2e-4);
  EXPECT_LT(std::stod(last[4]), std::stod(last[9]))
      << "greedy error " << last[4] << ", random median " << last[9];
  // The first step is the best single AP of all the candidates, so no random single AP beats it.
  EXPECT_LE(std::stod(csv[1][4]), std::stod(csv[1][9]) + 1e-9);

  // The block it writes replaces the scene's access points and loads: the chosen positions.
  std::string scene = test::read_file(kScenes + "/c_hall.yaml");
  const std::string own = "access_points: {placement: rooms, count: 38}\n";
  const auto at = scene.find(own);
  ASSERT_NE(at, std::string::npos);
  std::string block = test::read_file(out / "access_points.yaml");
  scene.replace(at, own.size(), block);
  const sim::scene::Scene loaded = sim::scene::load_scene_yaml(scene, "c_hall with the placed APs");
  ASSERT_EQ(loaded.access_points.explicit_list.size(), static_cast<std::size_t>(budget));
  for (int i = 0; i < budget; ++i) {
    const auto& row = csv[static_cast<std::size_t>(i + 1)];
    const Eigen::Vector3d p =
        loaded.access_points.explicit_list[static_cast<std::size_t>(i)].position_m;
    EXPECT_NEAR(p.x(), std::stod(row[1]), 1e-9);
    EXPECT_NEAR(p.y(), std::stod(row[2]), 1e-9);
  }

  // A budget over the candidates is bad input, and nothing is written.
  const auto too_many = test::run_wifislam("study place " + kScenes +
                                               "/c_hall.yaml --budget 2000 --spacing 50 -q -o " +
                                               (dir / "none").string(),
                                           dir);
  EXPECT_EQ(too_many.exit_code, 2) << too_many.err;
  EXPECT_NE(too_many.err.find("candidate positions"), std::string::npos) << too_many.err;
  EXPECT_FALSE(fs::exists(dir / "none"));
  // A route whose pauses are too short for a scan (the tiny loop's 1 s) has nothing to resolve.
  test::write_file(dir / "tiny.yaml", test::kTinyLoopYaml);
  const auto no_pauses = test::run_wifislam("study place " + (dir / "tiny.yaml").string() +
                                                " --budget 1 -q -o " + (dir / "none").string(),
                                            dir);
  EXPECT_EQ(no_pauses.exit_code, 2) << no_pauses.err;
  EXPECT_NE(no_pauses.err.find("route.pause"), std::string::npos) << no_pauses.err;
  EXPECT_FALSE(fs::exists(dir / "none"));
  // No front end runs here: a --set frontend= is refused without naming a flag place lacks.
  const auto frontend = test::run_wifislam(
      "study place " + kScenes + "/c_hall.yaml --budget 1 --set frontend=orbslam -q -o " +
          (dir / "none").string(),
      dir);
  EXPECT_EQ(frontend.exit_code, 2) << frontend.err;
  EXPECT_NE(frontend.err.find("runs no front end"), std::string::npos) << frontend.err;
  EXPECT_EQ(frontend.err.find("--frontend"), std::string::npos) << frontend.err;
  EXPECT_FALSE(fs::exists(dir / "none"));
  // Nor any other option but the Wi-Fi module's own: they changed nothing, silently.
  for (const char* setting : {"min_matches=10", "wifi_max_retrieved=2", "wifi=true"}) {
    const auto r = test::run_wifislam("study place " + kScenes + "/c_hall.yaml --budget 1 --set " +
                                          setting + " -q -o " + (dir / "none").string(),
                                      dir);
    EXPECT_EQ(r.exit_code, 2) << setting << ": " << r.err;
    EXPECT_NE(r.err.find("runs no front end"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "none"));
  }
  fs::remove_all(dir);
}

// A building of several levels: the candidates stand on the route's level (the one its pauses
// hear them from), and the block the study writes names it, so that pasted into the scene the
// chosen APs are where they were simulated.
TEST(StudyPlace, OnAnUpperLevelTheCandidatesAndTheirBlockAreOnTheRoutesLevel) {
  const fs::path dir = test::scratch_folder();
  const fs::path upstairs_path = test::write_upstairs_two_storey_office(dir);
  std::string upstairs = test::read_file(upstairs_path);
  const auto r = test::run_wifislam(
      "study place " + upstairs_path.string() + " --budget 2 -q -o " + (dir / "place").string(),
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string block = test::read_file(dir / "place" / "access_points.yaml");
  const std::string own = "access_points: {placement: rooms, count: 4, height_m: 2.5}\n";
  ASSERT_NE(upstairs.find(own), std::string::npos);
  upstairs.replace(upstairs.find(own), own.size(), block);
  const sim::scene::Scene loaded =
      sim::scene::load_scene_yaml(upstairs, "upstairs with the placed APs");
  ASSERT_EQ(loaded.access_points.explicit_list.size(), 2u);
  for (const sim::scene::AccessPointSpec& ap : loaded.access_points.explicit_list)
    EXPECT_EQ(ap.level, "first") << block;
  // Placed on the upper storey: 2.5 m above its floor at 3.1 m.
  const sim::site::Site site(loaded);
  for (const auto& ap : site.access_points()) EXPECT_NEAR(ap.position_m.z(), 3.1 + 2.5, 1e-9);
  fs::remove_all(dir);
}

TEST(StudyFile, ShippedStudiesLoadAndEveryCaseChecks) {
  const fs::path studies = fs::path(kScenes).parent_path() / "studies";
  int files = 0;
  for (const auto& entry : fs::directory_iterator(studies)) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().string());
    const StudyFile study = load_study_file(entry.path());
    EXPECT_FALSE(study.cases.empty());
    EXPECT_NO_THROW(check_cases(study));
    // The header states the number of cases it has.
    EXPECT_NE(test::read_file(entry.path()).find("= " + std::to_string(study.cases.size())),
              std::string::npos)
        << "the header's case count is not " << study.cases.size();
    ++files;
  }
  EXPECT_GE(files, 3);
}

}  // namespace
}  // namespace wifislam::study
