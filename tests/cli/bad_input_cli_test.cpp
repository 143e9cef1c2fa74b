// Hostile input never crashes the command line (issue 18, "Crashes"): numbers out of any
// physical range, heights outside the building, absurd thread counts under resource limits, a
// broken image, and SLAM options OpenCV cannot take all end in one located line on stderr and
// exit 2 (or, for threads, in a finished dataset), with no half-written output left behind.
#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/cli_run.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;
using test::run_wifislam;

class BadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_ = test::scratch_folder();
    scene_ = scratch_ / "tiny.yaml";
    test::write_file(scene_, test::kTinyLoopYaml);
  }
  void TearDown() override { fs::remove_all(scratch_); }

  test::CliResult wifislam(const std::string& args, const std::string& prefix = "") {
    return run_wifislam(args, scratch_, {}, prefix);
  }
  fs::path scene_with(const std::string& from, const std::string& to, const std::string& name) {
    return test::tiny_loop_with(scratch_, from, to, name);
  }

  fs::path scratch_, scene_;
};

// Once a SIGFPE in the exact floor-plan arithmetic (1e308), a bad_alloc after 15 s (1e9) and a
// route check running for minutes (1e5): coordinates are limited to 10 km.
// CLI::Range(a, b) passes nan (both of its comparisons are false): every bounded real option
// goes through cli::finite_range instead, and nan, inf or a value outside the bounds stop the
// command before it reads anything.
TEST_F(BadInput, BoundedRealOptionsRefuseNanAndInfinity) {
  const std::string scene = scene_.string(), out = (scratch_ / "out").string();
  const std::vector<std::string> commands = {
      "generate " + scene + " -o " + out + " --fps",
      "slam " + scene + " -o " + out + " --fps",
      "radiomap " + scene + " --strongest -o " + out + ".png --res",
      "radio calibrate survey.csv --scene " + scene + " --aps aps.csv -o " + out +
          ".yaml --frequency-mhz",
      "import plan.geojson -o " + out + ".yaml --wall-thickness",
      "localize " + scene + " -o " + out + " --map-share",
      "localize " + scene + " -o " + out + " --image-interval",
      "study place " + scene + " -o " + out + " --spacing",
  };
  for (const std::string& command : commands) {
    for (const char* value : {"nan", "inf", "-inf", "1e300"}) {
      const test::CliResult r = wifislam(command + " " + value);
      EXPECT_EQ(r.exit_code, 2) << command << " " << value << ": " << r.err;
      EXPECT_NE(r.err.find("expected a number in ["), std::string::npos)
          << command << " " << value << ": " << r.err;
      for (const char* suffix : {"", ".png", ".yaml"})
        EXPECT_FALSE(fs::exists(out + suffix)) << command << " " << value;
    }
  }
}

TEST_F(BadInput, CoordinatesBeyondTenKilometresAreLocatedErrors) {
  for (const std::string value : {"1e308", "1e9", "1e5", "-10000.5", ".nan", ".inf"}) {
    const fs::path scene =
        scene_with("position_m: [7, 0]", "position_m: [" + value + ", 0]", "far.yaml");
    const auto start = std::chrono::steady_clock::now();
    const auto r = wifislam("world " + scene.string());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    test::expect_located_bad_input(r, "far.yaml:8:", "nodes[1].position_m[0]");
    EXPECT_NE(r.err.find("[-10000, 10000]"), std::string::npos) << r.err;
    EXPECT_LT(seconds, 10.0) << value;
  }
  // Every other coordinate too: the corner of an open area, a colinear AP line.
  const fs::path area =
      scene_with("corridors:",
                 "open_areas:\n  - {id: hall, polygon_m: [[0, 0], [3, 0], [3, 1e12]]}\ncorridors:",
                 "area.yaml");
  test::expect_located_bad_input(wifislam("world " + area.string()),
                                 "area.yaml:", "open_areas[0].polygon_m[2][1]");
}

// A 50 MB scene file once took 4.8 GB of memory in the YAML reader: files over 4 MiB are refused
// before parsing, in a fraction of a second, naming the file and the limit. A 5 MB comment keeps
// the text valid YAML, so only the size is wrong with it.
TEST_F(BadInput, SceneFilesOverTheSizeLimitAreRefusedBeforeParsing) {
  const fs::path big = scratch_ / "big.yaml";
  test::write_file(big, std::string(test::kTinyLoopYaml) + "# " + std::string(5 << 20, 'x') + "\n");
  const auto start = std::chrono::steady_clock::now();
  const auto r = wifislam("world " + big.string());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  test::expect_located_bad_input(r, "big.yaml", "at most 4 MiB");
  EXPECT_LT(seconds, 5.0);
}

// Within the limits a building can still be 20 km long: the route's wall-clearance check and the
// AP candidate spots once scanned every wall face per point (over half a minute of CPU for this
// L; minutes for larger plans). Measured in the child's CPU seconds, so a busy machine does not
// make it fail.
TEST_F(BadInput, TheLargestBuildingsTheLimitsAllowBuildInSeconds) {
  const fs::path scene = scratch_ / "ell.yaml";
  test::write_file(scene, R"(version: 1
name: twenty_km_ell
seed: 1
nodes:
  - {id: A, position_m: [-10000, -10000]}
  - {id: B, position_m: [10000, -10000]}
  - {id: C, position_m: [10000, 10000]}
corridors:
  - {id: south, from: A, to: B, width_m: 2.0}
  - {id: east, from: B, to: C, width_m: 2.0}
access_points: {placement: rooms, count: 4}
route:
  nodes: [A, B, C]
)");
  rusage before{}, after{};
  ::getrusage(RUSAGE_CHILDREN, &before);
  const auto r = wifislam("world " + scene.string());
  ::getrusage(RUSAGE_CHILDREN, &after);
  const auto cpu_s = [](const rusage& u) {
    return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  };
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("route length: 39999."), std::string::npos) << r.out;
  EXPECT_LT(cpu_s(after) - cpu_s(before), 8.0);
}

// Once an Embree assertion (abort) that left DS.partial behind.
TEST_F(BadInput, AccessPointAboveTheBuildingIsALocatedError) {
  const fs::path scene = scene_with(
      "access_points: {placement: random, count: 8}",
      "access_points:\n  placement: explicit\n  list: [{position_m: [1, 0, 1e300]}]", "ap.yaml");
  const fs::path out = scratch_ / "ds";
  const auto r =
      wifislam("generate " + scene.string() + " -o " + out.string() + " --fps 2 --max-frames 2 -q");
  test::expect_located_bad_input(r, "ap.yaml:", "access_points.list[0].position_m[2]");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
  // Within the schema's range but above this building's 2.8 m ceiling.
  const fs::path high = scene_with("access_points: {placement: random, count: 8}",
                                   "access_points:\n  placement: explicit\n  list: [{position_m: "
                                   "[1, 0, 4.0]}]",
                                   "high.yaml");
  test::expect_located_bad_input(wifislam("world " + high.string()),
                                 "high.yaml:", "access_points.list[0].position_m[2]");
}

// Once an Embree assertion (abort) for nan, inf and 1e300.
TEST_F(BadInput, RadioMapHeightOutsideTheBuildingIsAnError) {
  const fs::path png = scratch_ / "map.png";
  for (const char* height : {"nan", "inf", "1e300", "-1", "0", "2.8"}) {
    const auto r = wifislam("radiomap " + scene_.string() + " --strongest --height " + height +
                            " -o " + png.string());
    test::expect_located_bad_input(r, "--height", "ceiling");
    EXPECT_FALSE(fs::exists(png)) << height;
  }
  const auto r = wifislam("radiomap " + scene_.string() +
                          " --strongest --res 0.5 --height 1.2 -o " + png.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(png));
}

// Once `terminate called without an active exception` (exit 134) and a DS.partial left behind:
// under a memory limit the system refuses most of 600 thread stacks. Thread counts are clamped,
// and whatever threads will not start are done without.
TEST_F(BadInput, HundredsOfThreadsUnderAMemoryLimitStillGiveADataset) {
  const fs::path out = scratch_ / "ds";
  // 256 MB default stacks against a 2 GB address space: a handful of such threads would exhaust
  // it and later allocations fail at random (bad_alloc, exit 70, one run in five); wifislam caps
  // its threads' default stack (core/thread_start.hpp), so every run gives a dataset.
  const auto r = wifislam("generate " + scene_.string() + " -o " + out.string() +
                              " --fps 2 --max-frames 4 --threads 600",
                          "ulimit -s 262144 && ulimit -v 2000000 && LP_NUM_THREADS=0");
  EXPECT_EQ(r.signal, 0) << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
  EXPECT_EQ(wifislam("check " + out.string()).exit_code, 0);
}

// Once an OpenCV assertion (exit 70) on the empty buffer.
TEST_F(BadInput, EmptyPngInADatasetWithoutManifestIsALocatedError) {
  const fs::path ds = scratch_ / "ds";
  ASSERT_EQ(
      wifislam("generate " + scene_.string() + " -o " + ds.string() + " --fps 2 --max-frames 3 -q")
          .exit_code,
      0);
  // Without manifest and marker: a plain TUM folder (with the marker alone it is an unfinished
  // dataset, refused before any image is read).
  fs::remove(ds / "manifest.json");
  fs::remove(ds / ".wifislam-output");
  fs::path png;
  for (const auto& e : fs::directory_iterator(ds / "rgb")) png = e.path();
  ASSERT_FALSE(png.empty());
  fs::resize_file(png, 0);
  const auto r = wifislam("check " + ds.string());
  test::expect_located_bad_input(r, png.filename().string(), "0 bytes");
}

// Once exit 70 from inside OpenCV's ORB (pyramid levels of no pixels, unbounded allocation).
TEST_F(BadInput, OrbOptionsOutsideTheirRangeAreErrors) {
  const fs::path ds = scratch_ / "ds";
  ASSERT_EQ(
      wifislam("generate " + scene_.string() + " -o " + ds.string() + " --fps 2 --max-frames 3 -q")
          .exit_code,
      0);
  const fs::path run = scratch_ / "run";
  for (const std::string setting :
       {"orb_levels=1000", "orb_scale_factor=1e308", "max_keypoints=2147483647",
        "orb_levels=20 --set orb_scale_factor=2"}) {
    const auto r = wifislam("slam " + ds.string() + " --set " + setting + " -o " + run.string());
    test::expect_located_bad_input(r, "SLAM option", setting.substr(0, setting.find('=')));
    EXPECT_FALSE(fs::exists(run)) << setting;
  }
  const auto r = wifislam("slam " + ds.string() +
                          " --set orb_levels=6 --set orb_scale_factor=2 -o " + run.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// Argument errors are bad input like any other (exit 2, CLI11's usage message), while --help and
// --version still exit 0.
TEST_F(BadInput, ArgumentErrorsExitTwoWithAUsageMessage) {
  const std::vector<std::string> argument_errors = {
      "generate " + scene_.string() + " -o x --no-such-option", "generate " + scene_.string(),
      "generate " + scene_.string() + " -o x --fps fast", "no-such-command"};
  for (const std::string& args : argument_errors) {
    const auto r = wifislam(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
    EXPECT_FALSE(fs::exists(scratch_ / "x")) << args;
  }
  EXPECT_EQ(wifislam("generate --help").exit_code, 0);
  EXPECT_EQ(wifislam("--version").exit_code, 0);
}

// `info` names every library whose version can change a result, each with a version: libpng and
// zlib write the PNGs whose bytes the datasets promise, and were missing.
TEST_F(BadInput, InfoGivesEveryLibrarysVersion) {
  const auto r = wifislam("info");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* library : {"OpenCV", "Embree", "Ceres", "Eigen", "CGAL", "GDAL", "PROJ", "GEOS",
                              "SQLite", "cairo", "OpenSSL", "libpng", "zlib", "nlohmann", "fmt"}) {
    const std::size_t at = r.out.find(std::string("\n") + library + " ");
    ASSERT_NE(at, std::string::npos) << library << "\n" << r.out;
    const std::string line = r.out.substr(at + 1, r.out.find('\n', at + 1) - at - 1);
    EXPECT_NE(line.find_first_of("0123456789"), std::string::npos) << line;
  }
}

// Issue 44: `--sweep min_matches=10 --sweep min_matches=20` ran one setting labelled with both
// values (the last won), and a key both --set and swept likewise; a swept value long enough to
// make a run folder's name exceed 255 bytes lost the whole comparison (exit 3).
TEST_F(BadInput, ASweptKeyIsGivenOnceAndLongSettingsGetShortFolders) {
  for (const std::string& repeated :
       {std::string("--sweep min_matches=10 --sweep min_matches=20"),
        std::string("--set min_matches=10 --sweep min_matches=20,30")}) {
    const test::CliResult r =
        wifislam("compare " + scene_.string() + " " + repeated + " --max-frames 4 --fps 2 -q -o " +
                 (scratch_ / "c").string());
    EXPECT_EQ(r.exit_code, 2) << repeated << ": " << r.err;
    EXPECT_NE(r.err.find("min_matches"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(scratch_ / "c"));
  }
  // A value of 300 characters (a system file's path, say): one folder, named in under 255 bytes.
  const std::string long_value = "0.9" + std::string(297, '0');
  const test::CliResult r =
      wifislam("compare " + scene_.string() + " --sweep wifi_similarity=" + long_value +
               " --max-frames 4 --fps 2 --no-plots -q -o " + (scratch_ / "c").string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  for (const auto& seed_dir : fs::directory_iterator(scratch_ / "c" / "runs")) {
    for (const auto& setting : fs::directory_iterator(seed_dir.path())) {
      EXPECT_LT(setting.path().filename().string().size(), 255u);
    }
  }
}

// Issue 44: a survey of only a header named no file ("0 position-AP links for 1 unknowns").
TEST_F(BadInput, ASurveyOfOnlyAHeaderIsNamed) {
  test::write_file(scratch_ / "survey.csv", "x_m,y_m,ap_id,rss_dbm\n");
  const test::CliResult r =
      wifislam("radio calibrate " + (scratch_ / "survey.csv").string() + " --scene " +
               scene_.string() + " -o " + (scratch_ / "fit.yaml").string());
  test::expect_located_bad_input(r, (scratch_ / "survey.csv").string(), "no survey rows");
  EXPECT_FALSE(fs::exists(scratch_ / "fit.yaml"));
}

// Issue 44: a trajectory was read whole before its lines were checked (a 2 GB file with a bad
// second line: 55 s and 5.9 GB). Readers stream now: the bad line stops the reading at once,
// whatever follows it.
TEST_F(BadInput, ABadLineStopsTheReadingThereWhateverFollows) {
  const fs::path ds = scratch_ / "ds";
  ASSERT_EQ(wifislam("generate " + scene_.string() + " --fps 1 --no-images -q -o " + ds.string())
                .exit_code,
            0);
  {
    std::ofstream out(scratch_ / "big.txt", std::ios::binary);
    out << "1700000000.0 0 0 0 0 0 0 1\nnot a pose\n";
    const std::string block(1 << 20, 'x');
    for (int i = 0; i < 300; ++i) out << block;  // 300 MB after the bad line, in one line
  }
  const auto start = std::chrono::steady_clock::now();
  const test::CliResult r = wifislam("eval " + (scratch_ / "big.txt").string() + " --gt " +
                                         ds.string() + " -o " + (scratch_ / "e").string(),
                                     "ulimit -v 2000000;");
  const double took_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  test::expect_located_bad_input(r, (scratch_ / "big.txt").string() + ":2", "");
  EXPECT_LT(took_s, 10.0);
  fs::remove(scratch_ / "big.txt");
}

// A dataset of poses, odometry and Wi-Fi only (generate --no-images): slam ran on it and wrote an
// empty run, exit 0. Refused by name, as export refuses it, and nothing is written.
TEST_F(BadInput, SlamOnADatasetWithoutImagesIsRefused) {
  const fs::path ds = scratch_ / "poses_only";
  ASSERT_EQ(wifislam("generate " + scene_.string() + " --fps 1 --max-frames 3 --no-images -q -o " +
                     ds.string())
                .exit_code,
            0);
  for (const char* wifi : {"", " --wifi"}) {
    const auto r = wifislam("slam " + ds.string() + wifi + " -o " + (scratch_ / "run").string());
    test::expect_located_bad_input(r, ds.string(), "has no images");
    EXPECT_FALSE(fs::exists(scratch_ / "run"));
  }
}

// compare's options refused before any dataset is rendered, each in its own words: fewer frames
// than the evaluation aligns (it failed after every run, naming a deleted folder), a scene without
// a name (its folders were "-seed7"), a swept key that is no option (the message named --set), and
// the `wifi` option, which every run overrides, and a front end given and swept.
TEST_F(BadInput, CompareRefusesWhatWouldFailOrChangeNothingBeforeAnyWork) {
  const fs::path nameless = scratch_ / "nameless.yaml";
  std::string yaml = test::kTinyLoopYaml;
  const std::size_t name_at = yaml.find("name:");
  ASSERT_NE(name_at, std::string::npos);
  yaml.erase(name_at, yaml.find('\n', name_at) - name_at + 1);
  test::write_file(nameless, yaml);
  const struct {
    std::string args, message;
  } cases[] = {
      {scene_.string() + " --max-frames 2", "--max-frames 2: every run is scored"},
      {nameless.string() + " --max-frames 4", "the scene has no name"},
      {scene_.string() + " --sweep nokey=1,2 --max-frames 4", "--sweep: key 'nokey'"},
      {scene_.string() + " --set wifi=true --max-frames 4", "'wifi' option would change nothing"},
      // --frontend and a swept front end: the flag was dropped without a word.
      {scene_.string() + " --frontend rtabmap --sweep frontend=rgbdslam,orbslam --max-frames 4",
       "the front end is also swept"},
  };
  for (const auto& c : cases) {
    const auto r = wifislam("compare " + c.args + " --fps 2 -q -o " + (scratch_ / "c").string());
    EXPECT_EQ(r.exit_code, 2) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(scratch_ / "c")) << c.args;
    EXPECT_FALSE(fs::exists(scratch_ / "c.partial")) << c.args;
  }
}

// A folder named in Latin-1: slam, eval and export failed with an internal error (exit 70) when
// the first JSON file naming it was written, after the work. Every argument must be UTF-8, checked
// before anything runs: exit 2, nothing written.
TEST_F(BadInput, AnArgumentThatIsNotUtf8IsRefusedBeforeAnyWork) {
  const fs::path latin1 = scratch_ / "d\xff\xfe";
  fs::create_directories(latin1);
  const fs::path out = scratch_ / "out";
  for (const std::string& args :
       {"slam '" + latin1.string() + "' -o " + out.string(),
        "generate " + scene_.string() + " --fps 1 --max-frames 2 -q -o '" + latin1.string() +
            "/ds'",
        "export '" + latin1.string() + "' --for euroc -o " + out.string()}) {
    const auto r = wifislam(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find("is not valid UTF-8"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(fs::is_empty(latin1));
}

}  // namespace
}  // namespace wifislam
