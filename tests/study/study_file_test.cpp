// Study files: located errors for bad input, "did you mean" for unknown axis keys, the cases as
// the product of the axes (or a listed subset) with stable ids, and shards that partition them.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>

#include "core/error.hpp"
#include "study/study_file.hpp"
#include "study/study_runner.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::study {
namespace {

const std::string kCHallScene = std::string(WIFISLAM_SCENES_DIR) + "/c_hall.yaml";

std::string study_yaml(const std::string& axes, const std::string& extra = "",
                       const std::string& level = "radio") {
  return "version: 1\nname: test\nscene: " + kCHallScene + "\nlevel: " + level + "\naxes:\n" +
         axes + extra;
}

std::string slam_study_yaml(const std::string& axes, const std::string& extra = "") {
  return study_yaml(axes, extra, "slam");
}

ParseError parse_error(const std::string& yaml) {
  try {
    load_study_yaml(yaml, "s.yaml");
  } catch (const ParseError& e) {
    return e;
  }
  ADD_FAILURE() << "no ParseError for:\n" << yaml;
  return ParseError("", "", "");
}

TEST(StudyFile, CasesAreTheProductOfTheAxesInOrderWithStableIds) {
  const StudyFile s = load_study_yaml(
      study_yaml("  access_points.count: [10, 20]\n  access_points.placement: [grid, rooms, "
                 "random]\n  slam.wifi_similarity: 0.9\n"),
      "s.yaml");
  ASSERT_EQ(s.cases.size(), 6u);
  EXPECT_EQ(s.cases[0].values, (std::vector<std::string>{"10", "grid", "0.9"}));
  EXPECT_EQ(s.cases[1].values, (std::vector<std::string>{"10", "rooms", "0.9"}));
  EXPECT_EQ(s.cases[5].values, (std::vector<std::string>{"20", "random", "0.9"}));
  EXPECT_EQ(s.axes[2].kind, AxisKind::kSlamOption);
  std::set<std::string> ids;
  for (const StudyCase& c : s.cases) ids.insert(c.id);
  EXPECT_EQ(ids.size(), 6u);
  EXPECT_EQ(s.cases[3].id.substr(0, 6), "00003-");
  // The same file reads to the same ids; a listed subset keeps the ids of the full product.
  EXPECT_EQ(load_study_yaml(study_yaml("  access_points.count: [10, 20]\n  "
                                       "access_points.placement: [grid, rooms, random]\n  "
                                       "slam.wifi_similarity: 0.9\n"),
                            "other.yaml")
                .cases[4]
                .id,
            s.cases[4].id);
  const StudyFile subset = load_study_yaml(
      study_yaml("  access_points.count: [10, 20]\n  access_points.placement: [grid, rooms, "
                 "random]\n  slam.wifi_similarity: 0.9\n",
                 "cases:\n  - {access_points.count: 20, access_points.placement: rooms, "
                 "slam.wifi_similarity: 0.9}\n"),
      "s.yaml");
  ASSERT_EQ(subset.cases.size(), 1u);
  EXPECT_EQ(subset.cases[0].id, s.cases[4].id);
}

TEST(StudyFile, ShardsPartitionTheCases) {
  const StudyFile s = load_study_yaml(study_yaml("  seed: [1, 2, 3, 4, 5, 6, 7]\n"), "s.yaml");
  std::multiset<std::string> seen;
  for (int i = 0; i < 3; ++i) {
    for (const StudyCase& c : shard_cases(s, i, 3)) {
      seen.insert(c.id);
      EXPECT_EQ(static_cast<int>(c.index % 3), i);
    }
  }
  EXPECT_EQ(seen.size(), s.cases.size());
  EXPECT_EQ(std::set<std::string>(seen.begin(), seen.end()).size(), s.cases.size());
}

TEST(StudyFile, MalformedFilesAreLocatedErrors) {
  // Unknown axis key: located on its line, with the closest scene key offered.
  auto e =
      parse_error(study_yaml("  access_points.count: [1]\n  access_point.placement: [grid]\n"));
  EXPECT_NE(e.where().find("s.yaml:7:3"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("did you mean 'access_points.placement'"), std::string::npos)
      << e.what();
  e = parse_error(study_yaml("  slam.min_matchs: [10]\n"));
  EXPECT_NE(std::string(e.what()).find("did you mean 'slam.min_matches'"), std::string::npos)
      << e.what();
  // Unknown top-level key, bad YAML, empty axis, repeated value, unknown front end.
  e = parse_error(study_yaml("  seed: [1]\n", "levle: slam\n"));
  EXPECT_EQ(e.key_path(), "levle");
  EXPECT_NE(std::string(e.what()).find("did you mean 'level'"), std::string::npos);
  e = parse_error("version: 1\nname: [unclosed\n");
  EXPECT_NE(e.where().find("s.yaml"), std::string::npos);
  e = parse_error(study_yaml("  seed: []\n"));
  EXPECT_EQ(e.key_path(), "axes.seed");
  e = parse_error(study_yaml("  seed: [1, 1]\n"));
  EXPECT_NE(std::string(e.what()).find("listed twice"), std::string::npos);
  // The same value however written, as its reader takes it: one case twice. The seed is read
  // by YAML (0x1 and 01 are 1); other numbers decimally (010 is ten, +10 and 10.0 are ten).
  for (const char* spelt : {"01", "0x1"}) {
    e = parse_error(study_yaml(std::string("  seed: [1, ") + spelt + "]\n"));
    EXPECT_NE(
        std::string(e.what()).find(std::string("values '1' and '") + spelt + "' are the same"),
        std::string::npos)
        << spelt << ": " << e.what();
  }
  for (const char* spelt : {"010", "+10", "10.0"}) {
    e = parse_error(slam_study_yaml(std::string("  slam.min_matches: [10, ") + spelt + "]\n"));
    EXPECT_NE(
        std::string(e.what()).find(std::string("values '10' and '") + spelt + "' are the same"),
        std::string::npos)
        << spelt << ": " << e.what();
  }
  EXPECT_EQ(
      load_study_yaml(slam_study_yaml("  slam.min_matches: [8, 010]\n"), "s.yaml").cases.size(),
      2u);
  EXPECT_EQ(load_study_yaml(study_yaml("  access_points.tx_power_dbm: [15, 15.5]\n"), "s.yaml")
                .cases.size(),
            2u);
  // A run on no frames, refused as --max-frames 0 is.
  e = parse_error(slam_study_yaml("  seed: [1]\n", "slam: {max_frames: 0}\n"));
  EXPECT_EQ(e.key_path(), "slam.max_frames");
  e = parse_error(study_yaml("  frontend: [rgbdslam, orbslam9]\n"));
  EXPECT_NE(std::string(e.what()).find("orbslam9"), std::string::npos);
  // A listed case that misses an axis or names a value the axis does not have.
  e = parse_error(
      study_yaml("  seed: [1, 2]\n  access_points.count: [5]\n", "cases:\n  - {seed: 1}\n"));
  EXPECT_EQ(e.key_path(), "cases[0]");
  e = parse_error(study_yaml("  seed: [1, 2]\n", "cases:\n  - {seed: 3}\n"));
  EXPECT_EQ(e.key_path(), "cases[0].seed");
  // Version and required keys.
  e = parse_error("version: 2\nname: x\nscene: a.yaml\naxes: {seed: [1]}\n");
  EXPECT_EQ(e.key_path(), "version");
  e = parse_error("version: 1\nname: x\naxes: {seed: [1]}\n");
  EXPECT_EQ(e.key_path(), "scene");
}

TEST(StudyFile, ACaseWhoseValueMakesNoValidSceneIsRefusedBeforeAnyWork) {
  const StudyFile s = load_study_yaml(study_yaml("  access_points.count: [5, -3]\n"), "s.yaml");
  try {
    check_cases(s);
    FAIL() << "a count of -3 was accepted";
  } catch (const ParseError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(s.cases[1].id), std::string::npos) << what;
    EXPECT_NE(what.find("access_points.count"), std::string::npos) << what;
  }
  // A wildcard over a list sets every element; a bad slam.* value is refused too.
  const StudyFile materials =
      load_study_yaml(study_yaml("  corridors[*].material: [concrete]\n"), "s.yaml");
  const sim::scene::Scene scene = case_scene(materials, materials.cases[0]);
  for (const sim::scene::Corridor& c : scene.corridors)
    EXPECT_EQ(c.material, radio_model::WallMaterial::kConcrete);
  const StudyFile bad_option =
      load_study_yaml(slam_study_yaml("  slam.min_matches: [2]\n"), "s.yaml");
  EXPECT_THROW(check_cases(bad_option), ParseError);
  // An element the scene does not have: the message named neither the study file nor the case.
  const StudyFile beyond =
      load_study_yaml(study_yaml("  corridors[99].material: [concrete]\n"), "s.yaml");
  try {
    check_cases(beyond);
    FAIL() << "corridors[99] was accepted";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.where(), "s.yaml");
    EXPECT_NE(std::string(e.what()).find(beyond.cases[0].id), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("corridors[99]"), std::string::npos) << e.what();
  }
}

TEST(StudyFile, SetGivesEveryCaseSceneKeysBeforeTheAxes) {
  const std::string axes = "  access_points.placement: [colinear]\n  access_points.count: [4, 8]\n";
  const StudyFile s = load_study_yaml(
      "version: 1\nname: test\nscene: " + kCHallScene +
          "\nset:\n  access_points.line_from_m: [2, 0]\n  access_points.line_to_m: [18, 0]\n"
          "  access_points.count: 99\naxes:\n" +
          axes,
      "s.yaml");
  ASSERT_EQ(s.cases.size(), 2u);
  const sim::scene::Scene scene = case_scene(s, s.cases[1]);
  EXPECT_EQ(scene.access_points.line_from_m, Eigen::Vector2d(2, 0));
  EXPECT_EQ(scene.access_points.line_to_m, Eigen::Vector2d(18, 0));
  EXPECT_EQ(scene.access_points.count, 8);  // the axis wins over `set`
  // An unknown key is located, with the closest scene key offered; a mapping value is refused.
  auto e = parse_error("version: 1\nname: t\nscene: " + kCHallScene +
                       "\nset:\n  access_points.line_too_m: [1, 1]\naxes:\n" + axes);
  EXPECT_NE(e.where().find("s.yaml:5:3"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("did you mean 'access_points.line_to_m'"), std::string::npos)
      << e.what();
  e = parse_error("version: 1\nname: t\nscene: " + kCHallScene +
                  "\nset:\n  access_points.line_to_m: {x: 1}\naxes:\n" + axes);
  EXPECT_EQ(e.key_path(), "set.access_points.line_to_m");
}

}  // namespace
}  // namespace wifislam::study

namespace wifislam::study {
namespace {

// Issue 44: contradicting front-end axes, and a front-end axis where no front end runs, were
// accepted (the second only repeated identical cases).
TEST(StudyFile, FrontEndAxesAreOneKindAndOnlyWhereAFrontEndRuns) {
  const std::string slam_study =
      "version: 1\nname: t\nscene: " + kCHallScene + "\nlevel: slam\naxes:\n";
  const ParseError both = parse_error(slam_study + "  frontend: [rgbdslam]\n  system: [rtabmap]\n");
  EXPECT_NE(std::string(both.what()).find("not both"), std::string::npos) << both.what();
  const ParseError radio = parse_error(study_yaml("  frontend: [rgbdslam, orbslam]\n"));
  EXPECT_NE(std::string(radio.what()).find("level radio runs no front end"), std::string::npos)
      << radio.what();
}

// A radio-level case reads the Wi-Fi module's options only: any other SLAM option, as an axis or
// a setting, and the slam block's front end, fps and frame count were accepted and changed no
// number (an axis of them ran identical cases). Refused, naming the key; the Wi-Fi ones still
// sweep.
TEST(StudyFile, ARadioLevelStudyRefusesSlamOptionsItDoesNotRead) {
  struct Refused {
    std::string axes, extra, key_path;
  };
  for (const Refused& r :
       std::vector<Refused>{{"  slam.min_matches: [10, 20]\n", "", "axes.slam.min_matches"},
                            {"  seed: [1]\n", "slam: {settings: {max_keypoints: 300}}\n",
                             "slam.settings.max_keypoints"},
                            {"  seed: [1]\n", "slam: {fps: 3}\n", "slam.fps"},
                            {"  seed: [1]\n", "slam: {frontend: orbslam}\n", "slam.frontend"},
                            {"  seed: [1]\n", "slam: {max_frames: 10}\n", "slam.max_frames"}}) {
    const ParseError e = parse_error(study_yaml(r.axes, r.extra));
    EXPECT_EQ(e.key_path(), r.key_path) << e.what();
    EXPECT_NE(std::string(e.what()).find("level radio renders nothing"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("wifi_similarity"), std::string::npos) << e.what();
    // The same study at level slam is read.
    EXPECT_NO_THROW(load_study_yaml(slam_study_yaml(r.axes, r.extra), "s.yaml")) << r.key_path;
  }
  const StudyFile wifi =
      load_study_yaml(study_yaml("  slam.wifi_similarity: [0.8, 0.9]\n",
                                 "slam: {settings: {wifi_floor_dbm: -90, wifi_pause_gap_s: 2}}\n"),
                      "s.yaml");
  EXPECT_EQ(wifi.cases.size(), 2u);
  EXPECT_EQ(wifi.slam.settings.size(), 2u);
}

// Each SLAM case runs vanilla and with Wi-Fi: a `wifi` option would be overridden by both.
TEST(StudyFile, TheWifiOptionIsRefusedAsAnAxisAndAsASetting) {
  ParseError e = parse_error(slam_study_yaml("  slam.wifi: [true, false]\n"));
  EXPECT_EQ(e.key_path(), "axes.slam.wifi");
  EXPECT_NE(std::string(e.what()).find("would change nothing"), std::string::npos) << e.what();
  e = parse_error(slam_study_yaml("  seed: [1]\n", "slam: {settings: {wifi: true}}\n"));
  EXPECT_EQ(e.key_path(), "slam.settings.wifi");
}

// Issue 44: `system: [../sys/x.yaml]` was read from the current folder while `scene:` is read
// from the study file's: a system file's relative path is the study file's now.
TEST(StudyFile, ASystemFilesRelativePathIsTheStudyFiles) {
  const std::filesystem::path dir = test::scratch_folder();
  std::filesystem::create_directories(dir / "studies");
  std::filesystem::create_directories(dir / "sys");
  {
    std::ofstream(dir / "sys" / "x.yaml") << "version: 1\nname: x\ncommand: [/bin/true]\n"
                                             "outputs: {trajectory: t.txt}\n";
    std::ofstream(dir / "studies" / "s.yaml")
        << "version: 1\nname: s\nscene: " << kCHallScene << "\nlevel: slam\naxes:\n  system: "
        << "[../sys/x.yaml, rgbdslam]\n";
  }
  // Loaded from a current folder where ../sys/x.yaml is not that file.
  const StudyFile s = load_study_file(dir / "studies" / "s.yaml");
  EXPECT_EQ(s.cases[0].values[0], "../sys/x.yaml");  // ids and columns keep the text
  EXPECT_EQ(axis_front_end(s, AxisKind::kSystem, "../sys/x.yaml"),
            "external:" + (dir / "sys" / "x.yaml").string());
  EXPECT_EQ(case_slam_options(s, s.cases[0]).frontend,
            "external:" + (dir / "sys" / "x.yaml").string());
  EXPECT_EQ(case_slam_options(s, s.cases[1]).frontend, "rgbdslam");
  // Its inputs: the study file, its scene and the system file (not the built-in front end).
  const std::vector<std::filesystem::path> inputs = input_files(s);
  ASSERT_EQ(inputs.size(), 3u);
  EXPECT_EQ(inputs[2], dir / "sys" / "x.yaml");
  std::filesystem::remove_all(dir);
}

// A study file is read as the scene loader reads YAML: a FIFO no program writes reads as empty
// (it hung), /dev/zero stops at the size cap (it grew to gigabytes), a folder is named as one.
TEST(StudyFile, AFifoAFolderAndAnEndlessFileAreRefusedByName) {
  const std::filesystem::path dir = test::scratch_folder();
  const std::filesystem::path fifo = dir / "s.yaml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  try {
    load_study_file(fifo);
    ADD_FAILURE() << "read a FIFO";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("the study file is empty"), std::string::npos) << e.what();
  }
  try {
    load_study_file("/dev/zero");
    ADD_FAILURE() << "read /dev/zero";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("at most 4 MiB"), std::string::npos) << e.what();
  }
  std::filesystem::create_directories(dir / "d.yaml");
  try {
    load_study_file(dir / "d.yaml");
    ADD_FAILURE() << "read a folder";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("is a folder"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

// Vocabulary files of the SLAM settings and of a slam.vocabulary axis are inputs too.
TEST(StudyFile, VocabularyFilesAreInputs) {
  const StudyFile s = load_study_yaml(
      "version: 1\nname: v\nscene: " + kCHallScene +
          "\nlevel: slam\nslam:\n  frontend: orbslam\n  settings: {vocabulary: /v/a.bin}\n"
          "axes:\n  slam.vocabulary: [/v/b.bin]\n",
      "s.yaml");
  const std::vector<std::filesystem::path> inputs = input_files(s);
  EXPECT_NE(std::find(inputs.begin(), inputs.end(), "/v/a.bin"), inputs.end());
  EXPECT_NE(std::find(inputs.begin(), inputs.end(), "/v/b.bin"), inputs.end());
}

// An option of a front end no case runs changes no row: said as `slam` and `compare` say it, in
// the study's own terms (its file), and not when a frontend axis runs the front end that reads it.
TEST(StudyFile, OptionsOfAFrontEndNoCaseRunsAreWarnedAbout) {
  const std::string head = "version: 1\nname: w\nscene: " + kCHallScene + "\nlevel: slam\n";
  const StudyFile unread =
      load_study_yaml(head +
                          "slam:\n  settings: {stm_size: 20, min_matches: 40}\naxes:\n"
                          "  slam.loop_consistency: [2, 3]\n",
                      "w.yaml");
  const std::vector<std::string> warnings = unread_option_warnings(unread);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("w.yaml: stm_size is an option of the rtabmap front end; rgbdslam "
                             "does not read it"),
            std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[1].find("loop_consistency is an option of the orbslam front end"),
            std::string::npos)
      << warnings[1];
  EXPECT_TRUE(
      unread_option_warnings(load_study_yaml(head + "slam:\n  settings: {stm_size: 20}\naxes:\n"
                                                    "  frontend: [rgbdslam, rtabmap]\n",
                                             "w.yaml"))
          .empty());
  EXPECT_TRUE(
      unread_option_warnings(load_study_yaml(head + "slam:\n  settings: {min_matches: 40}\naxes:\n"
                                                    "  seed: [1, 2]\n",
                                             "w.yaml"))
          .empty());
}

}  // namespace
}  // namespace wifislam::study
