// Messages a user can act on (issue 18, "Messages"): bad input found after the scene is loaded
// (the floor plan, AP placement) names the file, line, column and key like the loader's own
// errors, and exits 2; a folder given as a scene is refused alike by every command; a radio map
// too fine for memory says what resolution would do; a second run into a folder being written
// says so instead of "write failed (disk full?)".
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"
#include "tests/support/wait_until.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;
using test::run_wifislam;

class LocatedMessage : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_ = test::scratch_folder();
    scene_ = scratch_ / "tiny.yaml";
    test::write_file(scene_, test::kTinyLoopYaml);
  }
  void TearDown() override { fs::remove_all(scratch_); }

  test::CliResult wifislam(const std::string& args) { return run_wifislam(args, scratch_); }
  fs::path scene_with(const std::string& from, const std::string& to, const std::string& name) {
    return test::tiny_loop_with(scratch_, from, to, name);
  }

  fs::path scratch_, scene_;
};

// Once "open area 'hall': polygon_m must be a simple polygon" without file or line.
TEST_F(LocatedMessage, SelfIntersectingPolygonNamesItsLineAndKey) {
  const fs::path scene = scene_with(
      "corridors:",
      "open_areas:\n  - {id: hall, polygon_m: [[0, 0], [4, 4], [4, 0], [0, 4]]}\ncorridors:",
      "bowtie.yaml");
  test::expect_located_bad_input(wifislam("world " + scene.string()),
                                 "bowtie.yaml:12:", "key 'open_areas[0].polygon_m'");
  EXPECT_NE(wifislam("world " + scene.string()).err.find("crosses"), std::string::npos);
}

// Once "the floor plan has no free space at least 0.4 m from the walls" for a corridor of the
// schema's smallest width.
TEST_F(LocatedMessage, NarrowestCorridorsTakeAccessPoints) {
  std::string yaml = test::kTinyLoopYaml;
  for (std::size_t at; (at = yaml.find("width_m: 2.0")) != std::string::npos;) {
    yaml.replace(at, 12, "width_m: 0.8");
  }
  const fs::path scene = scratch_ / "narrow.yaml";
  test::write_file(scene, yaml);
  const auto r = wifislam("world " + scene.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("access points: 8"), std::string::npos) << r.out;
}

// AP placement that cannot be done is bad input located at the scene's access_points.
TEST_F(LocatedMessage, AccessPointsThatDoNotFitAreLocated) {
  const fs::path scene =
      scene_with("access_points: {placement: random, count: 8}",
                 "access_points: {placement: grid, count: 10000}", "crowded.yaml");
  test::expect_located_bad_input(wifislam("world " + scene.string()),
                                 "crowded.yaml:19:", "key 'access_points'");
}

// Once exit 105 (CLI11's check) in some commands and 3 in another.
TEST_F(LocatedMessage, AFolderGivenAsTheSceneIsBadInputInEveryCommand) {
  const fs::path folder = scratch_ / "folder.yaml";
  fs::create_directories(folder);
  const fs::path out = scratch_ / "out";
  for (const std::string& command :
       {"world " + folder.string(), "generate " + folder.string() + " -o " + out.string(),
        "radiomap " + folder.string() + " --strongest -o " + (scratch_ / "m.png").string(),
        "render " + folder.string() + " --pose 1,0,0 -o " + (scratch_ / "view").string(),
        "compare " + folder.string() + " -o " + out.string(), "demo --scene " + folder.string()}) {
    // In the scratch folder: the demo writes ./demo-output.
    test::expect_located_bad_input(run_wifislam(command, scratch_, scratch_), folder.string(),
                                   "is a folder");
  }
  // `slam` reads a folder as a dataset: this one is not one.
  test::expect_located_bad_input(wifislam("slam " + folder.string() + " -o " + out.string()),
                                 folder.string(), "not a dataset folder");
  EXPECT_FALSE(fs::exists(out));
  // A missing file is a file error (exit 3), the same in every command.
  const auto missing = wifislam("world " + (scratch_ / "nope.yaml").string());
  EXPECT_EQ(missing.exit_code, 3) << missing.err;
  EXPECT_NE(missing.err.find("nope.yaml"), std::string::npos) << missing.err;
}

// Once a 1 x 1 map for --res 1e-9 (the cell count overflowed an int).
TEST_F(LocatedMessage, RadioMapResolutionHasARangeAndTheMapACellLimit) {
  const fs::path png = scratch_ / "map.png";
  for (const char* res : {"1e-9", "0", "-1", "nan", "11"}) {
    const auto r = wifislam("radiomap " + scene_.string() + " --strongest --res " + res + " -o " +
                            png.string());
    EXPECT_NE(r.exit_code, 0) << res;
    EXPECT_NE(r.err.find("--res"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(png)) << res;
  }
  // 50 x 50 m at 1 cm would be 25 million cells.
  const fs::path ell = scratch_ / "ell.yaml";
  test::write_file(ell, R"(version: 1
name: ell
nodes:
  - {id: A, position_m: [0, 0]}
  - {id: B, position_m: [50, 0]}
  - {id: C, position_m: [50, 50]}
corridors:
  - {id: south, from: A, to: B}
  - {id: east, from: B, to: C}
access_points: {placement: random, count: 2}
route: {nodes: [A, B, C]}
)");
  const auto r =
      wifislam("radiomap " + ell.string() + " --strongest --res 0.01 -o " + png.string());
  test::expect_located_bad_input(r, "radio map", "at most 16 million cells");
  EXPECT_NE(r.err.find("--res"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(png));
}

// Once: the second run deleted the first one's staging folder, and the first failed with
// "write failed (disk full?)". The first run is stopped (SIGSTOP) once it writes, so the second
// surely meets it mid-write, then continued (SIGCONT) to finish its dataset.
TEST_F(LocatedMessage, SecondGenerateIntoAFolderBeingWrittenIsRefused) {
  const fs::path out = scratch_ / "ds", partial = scratch_ / "ds.partial";
  const fs::path first_rc = scratch_ / "first_rc.txt", first_pid = scratch_ / "first_pid.txt";
  const std::string first =
      "( " + std::string(WIFISLAM_BINARY) + " generate " + scene_.string() + " -o " + out.string() +
      " --fps 10 --max-frames 150 --threads 1 -q >'" + (scratch_ / "first_out.txt").string() +
      "' 2>'" + (scratch_ / "first_err.txt").string() + "' & echo $! >'" + first_pid.string() +
      ".tmp' && mv '" + first_pid.string() + ".tmp' '" + first_pid.string() +
      "'; wait $!; echo $? >'" + first_rc.string() + ".tmp' && mv '" + first_rc.string() +
      ".tmp' '" + first_rc.string() + "' ) &";
  ASSERT_EQ(std::system(first.c_str()), 0);
  test::wait_until(
      std::chrono::minutes(2),
      [&] {
        return (fs::exists(first_pid) && fs::exists(partial / "rgb")) || fs::exists(first_rc);
      },
      std::chrono::milliseconds(20));
  ASSERT_TRUE(fs::exists(partial / "rgb")) << "the first run never started writing";
  const pid_t pid = static_cast<pid_t>(std::stol(test::read_file(first_pid)));
  ASSERT_EQ(::kill(pid, SIGSTOP), 0) << "the first run ended before the second could meet it";
  const auto second =
      wifislam("generate " + scene_.string() + " -o " + out.string() + " --fps 10 -q");
  ASSERT_EQ(::kill(pid, SIGCONT), 0);
  ASSERT_TRUE(test::wait_until(std::chrono::minutes(2), [&] { return fs::exists(first_rc); }));
  test::expect_located_bad_input(second, out.string(),
                                 "another wifislam run is writing this folder");
  EXPECT_EQ(test::read_file(first_rc), "0\n") << test::read_file(scratch_ / "first_err.txt");
  EXPECT_EQ(wifislam("check " + out.string()).exit_code, 0);
  // The lock goes with the run: a later run, with --force, replaces the folder.
  EXPECT_EQ(wifislam("generate " + scene_.string() + " -o " + out.string() +
                     " --fps 2 --max-frames 2 -q --force")
                .exit_code,
            0);
}

}  // namespace
}  // namespace wifislam
