// `wifislam compare --preset paper-rgbdslam`: the paper's RGBD-SLAM experiment built in (the c_hall
// twin, min_matches 50 and 70), with options given on the command line winning over the preset's.
// Cut to 30 frames and one seed here; the full preset is a benchmark-length run.

#include <gtest/gtest.h>

#include <unistd.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/read_file.hpp"
#include "tests/support/scratch_folder.hpp"

namespace {

namespace fs = std::filesystem;

TEST(ComparePreset, PaperRgbdslamRunsTheCHallTwinAtMinMatches50And70) {
  const fs::path dir = wifislam::test::scratch_folder();
  const std::string command = std::string(WIFISLAM_BINARY) +
                              " compare --preset paper-rgbdslam --seeds 1 --max-frames 30 "
                              "--no-plots -q -o " +
                              (dir / "out").string() + " > " + (dir / "log.txt").string() + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << wifislam::test::read_file(dir / "log.txt");
  const std::string md = wifislam::test::read_file(dir / "out" / "comparison.md");
  EXPECT_NE(md.find("| c_hall |"), std::string::npos) << md;
  EXPECT_NE(md.find("min_matches=50 Vanilla"), std::string::npos) << md;
  EXPECT_NE(md.find("min_matches=70 WiFi"), std::string::npos) << md;
  EXPECT_NE(md.find("Bounded-module time, WiFi / Vanilla"), std::string::npos) << md;
  // --seeds 1 won over the preset's 5: one dataset.
  EXPECT_EQ(
      std::distance(fs::directory_iterator(dir / "out" / "datasets"), fs::directory_iterator{}), 1);
  fs::remove_all(dir);
}

TEST(ComparePreset, NoScenesAndNoPresetIsAnError) {
  const std::string command = std::string(WIFISLAM_BINARY) + " compare -o /nonexistent/x 2>&1";
  EXPECT_EQ(WEXITSTATUS(std::system(command.c_str())), 2);
}

// The preset is the c_hall twin's experiment: given a scene file too, it ran its settings on that
// scene instead, as if the scene were the twin.
TEST(ComparePreset, ASceneFileWithThePresetIsAnError) {
  const fs::path dir = wifislam::test::scratch_folder();
  const std::string command = std::string(WIFISLAM_BINARY) + " compare " + WIFISLAM_SCENES_DIR +
                              "/a_hall.yaml --preset paper-rgbdslam --max-frames 3 -o " +
                              (dir / "out").string() + " > " + (dir / "log.txt").string() + " 2>&1";
  EXPECT_EQ(WEXITSTATUS(std::system(command.c_str())), 2);
  EXPECT_NE(wifislam::test::read_file(dir / "log.txt").find("give no scene file"),
            std::string::npos)
      << wifislam::test::read_file(dir / "log.txt");
  EXPECT_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}

}  // namespace
