// Issue 34, through the command line on a small generated dataset: nothing is written inside an
// input, `check` refuses what `slam` refuses (unfinished datasets, zero frames, equal stamps),
// and every bad input is exit 2 naming the file (and line), never exit 3 or a silent pass.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <string>
#include <vector>

#include "tests/cli/shared_dataset.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;

class EdgeInput : public ::testing::Test {
 protected:
  // One dataset for the suite (generating is most of its time); tests edit copies of it.
  static void SetUpTestSuite() {
    dataset_ = test::shared_dataset(test::kTinyLoopYaml, "--fps 2 --max-frames 12 --threads 2");
  }
  void SetUp() override {
    ASSERT_FALSE(dataset_.empty()) << "wifislam generate failed";
    scratch_ = test::scratch_folder();
  }
  void TearDown() override { fs::remove_all(scratch_); }
  test::CliResult wifislam(const std::string& args) { return test::run_wifislam(args, scratch_); }
  /// A copy of the generated dataset to edit, named `name` in the scratch folder.
  fs::path copy(const std::string& name) {
    const fs::path to = scratch_ / name;
    fs::copy(dataset_, to, fs::copy_options::recursive);
    return to;
  }
  /// The copy without its manifest and marker: a plain TUM RGB-D folder, read without checksums.
  fs::path plain_copy(const std::string& name) {
    const fs::path to = copy(name);
    fs::remove(to / "manifest.json");
    fs::remove(to / ".wifislam-output");
    return to;
  }
  /// Exit 2 with every one of `parts` in the message, and nothing written at `run` (if given).
  static void expect_refused(const test::CliResult& r, const std::vector<std::string>& parts) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    for (const std::string& part : parts) {
      EXPECT_NE(r.err.find(part), std::string::npos) << "'" << part << "' in: " << r.err;
    }
  }
  static inline fs::path dataset_;
  fs::path scratch_;
};

TEST_F(EdgeInput, SlamNeverWritesItsRunInsideTheDataset) {
  const fs::path ds = copy("ds");
  const auto before = test::listing(ds);
  for (const char* force : {"", " --force"}) {
    const auto r = wifislam("slam " + ds.string() + " -o " + (ds / "run").string() + force);
    expect_refused(r, {"inside an input", (ds / "run").string()});
  }
  EXPECT_EQ(test::listing(ds), before);
}

// Before: the 1e308 m positions failed in the plot (exit 3, "cannot create drawing surface", no
// location) and the repeated line was scored.
TEST_F(EdgeInput, EvalRefusesANonPhysicalOrRepeatedPoseAtItsLine) {
  const fs::path trajectory = scratch_ / "traj.txt";
  const auto pose = [](int s, const char* xy) {
    return "170000000" + std::to_string(s) + ".000000 " + xy + " 0 0 0 0 1\n";
  };
  const fs::path gt = dataset_;
  const std::string eval =
      "eval " + trajectory.string() + " --gt " + gt.string() + " -o " + (scratch_ / "ev").string();
  test::write_file(trajectory,
                   pose(0, "0 0") + pose(1, "1e308 1e308") + pose(2, "0 0") + pose(3, "0 0"));
  expect_refused(wifislam(eval), {trajectory.string() + ":2", "not a physical position"});
  EXPECT_FALSE(fs::exists(scratch_ / "ev"));
  test::write_file(trajectory, pose(0, "0 0") + pose(1, "0 0") + pose(1, "0 0") + pose(2, "0 0") +
                                   pose(3, "0 0"));
  expect_refused(wifislam(eval), {trajectory.string() + ":3", "not later than the previous line"});
  EXPECT_FALSE(fs::exists(scratch_ / "ev"));
}

TEST_F(EdgeInput, CheckRefusesAnUnfinishedDatasetAsSlamDoes) {
  // What a generate killed at once leaves: the staging folder with its marker, nothing else.
  const fs::path partial = scratch_ / "sk.partial";
  fs::create_directories(partial);
  test::write_file(partial / ".wifislam-output", "");
  const auto check = wifislam("check " + partial.string());
  expect_refused(check, {"unfinished dataset"});
  const auto slam = wifislam("slam " + partial.string() + " -o " + (scratch_ / "run").string());
  expect_refused(slam, {"unfinished dataset"});
  // With --no-verify it is read, and holds no frames: still bad input.
  EXPECT_EQ(wifislam("check --no-verify " + partial.string()).exit_code, 2);
  // Killed later: lists without a manifest.
  const fs::path late = copy("late.partial");
  fs::remove(late / "manifest.json");
  expect_refused(wifislam("check " + late.string()), {"unfinished dataset"});
  EXPECT_EQ(wifislam("check --no-verify " + late.string()).exit_code, 0);
}

TEST_F(EdgeInput, ZeroFramesAreBadInputForCheckAndSlam) {
  const fs::path empty_assoc = plain_copy("empty_assoc");
  test::write_file(empty_assoc / "associations.txt", "");
  const fs::path empty_rgb = plain_copy("empty_rgb");
  fs::remove(empty_rgb / "associations.txt");
  test::write_file(empty_rgb / "rgb.txt", "# timestamp filename\n");
  for (const fs::path& ds : {empty_assoc, empty_rgb}) {
    for (const char* verify : {"", "--no-verify "}) {
      expect_refused(wifislam(std::string("check ") + verify + ds.string()), {"no"});
    }
    const fs::path run = scratch_ / "run";
    expect_refused(wifislam("slam " + ds.string() + " -o " + run.string()), {ds.string()});
    EXPECT_FALSE(fs::exists(run));
  }
  expect_refused(wifislam("check " + empty_assoc.string()), {"lists no frames"});
  expect_refused(wifislam("check " + empty_rgb.string()), {"rgb.txt lists no images"});
}

TEST_F(EdgeInput, TwoFramesStampedAlikeAreRefusedByCheckAndSlam) {
  const fs::path ds = copy("twins");
  const std::string assoc = test::read_file(ds / "associations.txt");
  std::string::size_type start = 0;
  while (assoc[start] == '#') start = assoc.find('\n', start) + 1;
  const std::string first = assoc.substr(start, assoc.find('\n', start) + 1 - start);
  test::write_file(ds / "associations.txt", assoc.substr(0, start) + first + assoc.substr(start));
  const std::string line = ds.string() + "/associations.txt:";
  expect_refused(wifislam("check --no-verify " + ds.string()), {line, "not later"});
  expect_refused(wifislam("slam --no-verify " + ds.string() + " -o " + (scratch_ / "run").string()),
                 {line, "not later"});
  EXPECT_FALSE(fs::exists(scratch_ / "run"));
}

TEST_F(EdgeInput, AnImageThatIsADeviceOrAFolderIsBadInputAndSoIsAFileForADataset) {
  const fs::path ds = plain_copy("devices");
  std::string rgb_image;
  for (const auto& e : fs::directory_iterator(ds / "rgb")) {
    rgb_image = e.path().string();
    break;
  }
  ASSERT_FALSE(rgb_image.empty());
  fs::remove(rgb_image);
  fs::create_symlink("/dev/zero", rgb_image);
  expect_refused(wifislam("check " + ds.string()), {rgb_image, "not a regular file"});
  fs::remove(rgb_image);
  fs::create_directories(rgb_image);
  expect_refused(wifislam("check " + ds.string()), {rgb_image, "is a folder, not a PNG image"});
  // `check FILE`: there, and not a dataset folder.
  expect_refused(wifislam("check " + (dataset_ / "scene.yaml").string()),
                 {"not a dataset folder (it is a file)"});
  EXPECT_EQ(wifislam("check " + (scratch_ / "none").string()).exit_code, 3);
}

// What is there but of the wrong kind is bad input (exit 2), not a missing file (exit 3) or one
// silently left out: a run folder's files, the dataset given as a file, a device as the input.
TEST_F(EdgeInput, EvalRefusesAFolderOrDeviceInPlaceOfAFile) {
  const fs::path run = scratch_ / "run";
  ASSERT_EQ(wifislam("slam " + dataset_.string() + " -o " + run.string()).exit_code, 0);
  for (const char* name : {"trajectory.txt", "keyframes.txt", "graph.json", "timing.json"}) {
    const fs::path edited = scratch_ / (std::string("edited_") + name);
    fs::copy(run, edited, fs::copy_options::recursive);
    fs::remove(edited / name);
    fs::create_directories(edited / name);
    expect_refused(
        wifislam("eval " + edited.string() + " --gt " + dataset_.string() + " --no-plots"),
        {(edited / name).string(), "is a folder; expected a file"});
    EXPECT_FALSE(fs::exists(edited / "eval")) << name;
  }
  expect_refused(
      wifislam("eval " + run.string() + " --gt " + (dataset_ / "groundtruth.txt").string() +
               " --no-plots -o " + (scratch_ / "e1").string()),
      {"groundtruth.txt: is not a folder"});
  expect_refused(wifislam("eval /dev/null --gt " + dataset_.string() + " --no-plots -o " +
                          (scratch_ / "e2").string()),
                 {"/dev/null: is neither a run folder nor a trajectory file"});
  EXPECT_EQ(wifislam("eval " + (scratch_ / "none").string() + " --gt " + dataset_.string() +
                     " --no-plots")
                .exit_code,
            3);
}

// A run folder given for a dataset is named as one: it carries this tool's marker and no
// manifest, so it read as "an unfinished dataset ... or pass --no-verify", advice that then failed
// again. A folder that holds no dataset file is bad input for eval's --gt, as for `check`.
TEST_F(EdgeInput, ARunFolderOrAnEmptyFolderGivenForADatasetIsNamedAsSuch) {
  const fs::path run = scratch_ / "run";
  ASSERT_EQ(wifislam("slam " + dataset_.string() + " -o " + run.string()).exit_code, 0);
  const std::string run_folder = run.string() + ": a SLAM run folder (it holds run.json)";
  expect_refused(wifislam("check " + run.string()), {run_folder});
  for (const char* verify : {"", " --no-verify"}) {
    expect_refused(wifislam("slam " + run.string() + verify + " -o " + (scratch_ / "r2").string()),
                   {run_folder});
    EXPECT_FALSE(fs::exists(scratch_ / "r2"));
  }
  expect_refused(
      wifislam("export " + run.string() + " --for orbslam2 -o " + (scratch_ / "x").string()),
      {run_folder});
  expect_refused(wifislam("eval " + run.string() + " --gt " + run.string() + " --no-plots -o " +
                          (scratch_ / "e1").string()),
                 {run_folder});
  fs::create_directories(scratch_ / "empty");
  for (const std::string& command :
       {std::string("check "),
        "eval " + run.string() + " --no-plots -o " + (scratch_ / "e2").string() + " --gt "}) {
    expect_refused(wifislam(command + (scratch_ / "empty").string()),
                   {(scratch_ / "empty").string() + ": not a dataset folder"});
  }
  EXPECT_FALSE(fs::exists(scratch_ / "e1"));
  EXPECT_FALSE(fs::exists(scratch_ / "e2"));
}

// A trajectory from a pipe (`<(...)` in a shell) reads as a file does (docs/input_output.md); its
// evaluation has no folder to go beside, so it needs -o, refused before the pipe is read.
TEST_F(EdgeInput, EvalReadsATrajectoryFromAPipe) {
  const fs::path trajectory = dataset_ / "groundtruth.txt";
  const test::CliResult from_file =
      wifislam("eval " + trajectory.string() + " --gt " + dataset_.string() + " --no-plots -o " +
               (scratch_ / "from_file").string());
  ASSERT_EQ(from_file.exit_code, 0) << from_file.err;
  const fs::path fifo = scratch_ / "trajectory.fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  expect_refused(wifislam("eval " + fifo.string() + " --gt " + dataset_.string() + " --no-plots"),
                 {fifo.string(), "give the output folder (-o)"});
  const std::string writer = "cat '" + trajectory.string() + "' >'" + fifo.string() + "' & ";
  const test::CliResult from_pipe =
      test::run_wifislam("eval " + fifo.string() + " --gt " + dataset_.string() +
                             " --no-plots -o " + (scratch_ / "from_pipe").string(),
                         scratch_, {}, writer);
  // Had eval not read the pipe, the writer would wait for a reader for ever: opening and closing
  // it here ends the writer either way.
  const int release_writer = open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  if (release_writer >= 0) close(release_writer);
  ASSERT_EQ(from_pipe.exit_code, 0) << from_pipe.err;
  const auto first_line = [](const std::string& text) { return text.substr(0, text.find('\n')); };
  EXPECT_EQ(first_line(from_pipe.out), first_line(from_file.out));
  EXPECT_NE(from_pipe.out.find("poses"), std::string::npos) << from_pipe.out;
}

// `eval ds/groundtruth.txt --gt ds`: the default output <file>_eval would be written into the
// dataset it reads; refused, by default or named, and the dataset is left as it was.
TEST_F(EdgeInput, EvalNeverWritesItsDefaultOutputIntoTheGroundTruthsDataset) {
  const fs::path ds = copy("ds");
  const auto before = test::listing(ds);
  const std::string trajectory = (ds / "groundtruth.txt").string();
  for (const std::string& output : {std::string(), " -o " + (ds / "groundtruth_eval").string()}) {
    expect_refused(wifislam("eval " + trajectory + " --gt " + ds.string() + " --no-plots" + output),
                   {"inside an input", ds.string()});
  }
  EXPECT_EQ(test::listing(ds), before);
  // Beside the dataset it is written as before.
  EXPECT_EQ(wifislam("eval " + trajectory + " --gt " + ds.string() + " --no-plots -o " +
                     (scratch_ / "gt_eval").string())
                .exit_code,
            0);
}

// calibration.yaml is copied into other programs' settings by export: values no camera has are
// refused at their line and key, with or without checksums, and a folder in its place is not
// the default Kinect intrinsics.
TEST_F(EdgeInput, CalibrationValuesNoCameraHasAreRefusedAndSoIsAFolder) {
  const std::string calibration = test::read_file(dataset_ / "calibration.yaml");
  const auto edited = [&](const std::string& key, const std::string& value) {
    const auto at = calibration.find(key + ": ");
    EXPECT_NE(at, std::string::npos) << key;
    const auto end = calibration.find_first_of(",}\n", at);
    std::string text = calibration;
    text.replace(at, end - at, key + ": " + value);
    return text;
  };
  const struct {
    const char* key;
    const char* value;
    const char* message;
  } cases[] = {{"fx_px", "1e308", "camera.fx_px"},
               {"cx_px", "-3", "camera.cx_px"},
               {"fps", "-1", "camera.fps"},
               {"units_per_metre", "1e300", "depth.units_per_metre"}};
  for (const auto& c : cases) {
    const fs::path ds = plain_copy(std::string("calibration_") + c.key);
    test::write_file(ds / "calibration.yaml", edited(c.key, c.value));
    expect_refused(wifislam("check " + ds.string() + " --no-images"),
                   {(ds / "calibration.yaml").string() + ":", c.message});
    expect_refused(wifislam("export " + ds.string() + " --for orbslam2 -o " +
                            (scratch_ / (std::string("export_") + c.key)).string()),
                   {c.message});
    EXPECT_FALSE(fs::exists(scratch_ / (std::string("export_") + c.key)));
  }
  const fs::path ds = plain_copy("calibration_folder");
  fs::remove(ds / "calibration.yaml");
  fs::create_directories(ds / "calibration.yaml");
  expect_refused(wifislam("check " + ds.string() + " --no-images"),
                 {(ds / "calibration.yaml").string(), "is a folder; expected a file"});
}

// A file written by renaming <file>.partial over it would replace a pipe or device: refused
// before any work. A command writing two files checks both first, so a --csv it cannot write
// leaves the user's PNG as it was.
TEST_F(EdgeInput, OutputFilesAreNeverPipesAndBothOfRadiomapsAreCheckedFirst) {
  const fs::path scene = scratch_ / "scene.yaml";
  test::write_file(scene, test::kTinyLoopYaml);
  const fs::path pipe = scratch_ / "pipe.png";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  expect_refused(wifislam("radiomap " + scene.string() + " --strongest -o " + pipe.string()),
                 {pipe.string(), "not a regular file"});
  expect_refused(wifislam("world " + scene.string() + " --plan " + pipe.string()),
                 {pipe.string(), "not a regular file"});
  EXPECT_TRUE(fs::is_fifo(pipe));
  const fs::path mine = scratch_ / "mine.png";
  test::write_file(mine, "mine");
  const auto r = wifislam("radiomap " + scene.string() + " --strongest -o " + mine.string() +
                          " --csv " + (scratch_ / "missing" / "map.csv").string());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  expect_refused(wifislam("radiomap " + scene.string() + " --strongest -o " + mine.string() +
                          " --csv " + pipe.string()),
                 {pipe.string(), "not a regular file"});
  EXPECT_EQ(test::read_file(mine), "mine");
}

// A scene's name becomes folder names (compare's datasets/<name>-seed<seed>): a name with '/'
// or ".." would write outside the output folder. Refused at its line, before any work.
TEST_F(EdgeInput, ASceneNameThatCannotNameAFolderIsRefused) {
  const fs::path scene =
      test::tiny_loop_with(scratch_, "name: cli_tiny_loop", "name: \"../escaped\"", "named.yaml");
  const fs::path out = scratch_ / "out" / "compare";
  fs::create_directories(out.parent_path());
  test::expect_located_bad_input(wifislam("compare " + scene.string() +
                                          " --fps 1 --max-frames 4 --no-plots -o " + out.string()),
                                 scene.string() + ":2:", "not a scene name");
  EXPECT_EQ(test::listing(scratch_ / "out"), std::vector<std::string>{});
  EXPECT_FALSE(fs::exists(scratch_ / "escaped-seed91"));
}

TEST_F(EdgeInput, SetFrontendCannotOverrideFrontend) {
  const fs::path run = scratch_ / "run";
  const auto r = wifislam("slam " + dataset_.string() +
                          " --frontend orbslam --set frontend=rtabmap -o " + run.string());
  expect_refused(r, {"--set", "conflicts with --frontend orbslam"});
  EXPECT_FALSE(fs::exists(run));
}

// An output path given as "" was taken for one not given: `render -o ""` wrote _rgb.png and two
// more files into the current folder, `radiomap -o ""` did its work and failed to rename, and
// `world --plan ""` drew nothing without a word. Each is refused before any work, naming the
// option, and nothing is written.
TEST_F(EdgeInput, AnEmptyOutputPathIsRefusedNamingItsOption) {
  const fs::path work = scratch_ / "work";
  fs::create_directories(work);
  const std::string scene = std::string(WIFISLAM_SCENES_DIR) + "/a_hall.yaml";
  const struct {
    std::string args, option;
  } cases[] = {{"render " + scene + " --pose 1,1,0 -o ''", "--output"},
               {"radiomap " + scene + " -o ''", "--output"},
               {"radiomap " + scene + " -o map.png --csv ''", "--csv"},
               {"world " + scene + " --plan ''", "--plan"},
               {"paper -o ''", "--output"}};
  for (const auto& c : cases) {
    const test::CliResult r = test::run_wifislam(c.args, scratch_, work);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.option + ": the path is empty"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::is_empty(work)) << c.args;
  }
}

// An input given as '' was reported as ": not found", ": cannot open for reading" and the like
// (exit 3, naming no file), and `localize --vocabulary ''` or `generate --device ''` silently used
// the default. Each is refused naming its option, before anything is read or written.
TEST_F(EdgeInput, AnEmptyInputPathIsRefusedNamingItsOption) {
  const fs::path work = scratch_ / "work";
  fs::create_directories(work);
  const std::string scene = std::string(WIFISLAM_SCENES_DIR) + "/a_hall.yaml";
  const struct {
    std::string args, message;
  } cases[] = {{"generate '' -o ds", "scene: the path is empty"},
               {"generate " + scene + " --device '' -o ds", "--device: empty"},
               {"slam '' -o run", "input: the path is empty"},
               {"eval '' --gt ds", "run: the path is empty"},
               {"eval run --gt ''", "--gt: the path is empty"},
               {"check ''", "dataset: the path is empty"},
               {"compare '' -o c", "scenes: the path is empty"},
               {"localize " + scene + " --vocabulary '' -o loc", "--vocabulary: the path is empty"},
               {"study run '' -o s.sqlite", "file: the path is empty"},
               {"radio calibrate s.csv --scene ''", "--scene: the path is empty"},
               {"radio calibrate s.csv --scene " + scene + " --test ''", "--test: the path is"},
               {"demo --scene '' -o d", "--scene: the path is empty"},
               {"localize " + scene + " --queries-session 2 --queries-device '' -o loc",
                "--queries-device: empty"}};
  for (const auto& c : cases) {
    const test::CliResult r = test::run_wifislam(c.args, scratch_, work);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_TRUE(fs::is_empty(work)) << c.args;
  }
}

}  // namespace
}  // namespace wifislam
