// No command deletes what the user did not ask to delete (core/output_folder.hpp): the cases of
// issue 18, run through the real binary on a real small dataset and SLAM run in a scratch folder.
#include <filesystem>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;
using test::listing;
using test::run_wifislam;

class OutputFolders : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_ = test::scratch_folder();
    work_ = scratch_ / "work";
    fs::create_directories(work_);
    scene_ = work_ / "tiny.yaml";
    test::write_file(scene_, test::kTinyLoopYaml);
  }
  void TearDown() override { fs::remove_all(scratch_); }

  test::CliResult wifislam(const std::string& args, const fs::path& cwd = {},
                           const std::string& prefix = "") {
    return run_wifislam(args, scratch_, cwd, prefix);
  }
  fs::path make_dataset() {
    const fs::path ds = work_ / "ds";
    const auto r = wifislam("generate " + scene_.string() + " -o " + ds.string() +
                            " --fps 2 --max-frames 12 --threads 2 -q");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return ds;
  }
  fs::path make_run(const fs::path& ds) {
    const fs::path run = work_ / "run";
    const auto r = wifislam("slam " + ds.string() + " -o " + run.string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return run;
  }
  // A folder of the user's: no marker, no manifest, not empty.
  fs::path user_folder(const std::string& name) {
    const fs::path dir = work_ / name;
    test::write_file(dir / "thesis.tex", "years of work");
    return dir;
  }
  static void expect_refused(const test::CliResult& r, const fs::path& path,
                             const std::string& reason) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(path.filename().string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(reason), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  }

  fs::path scratch_, work_, scene_;
};

TEST_F(OutputFolders, EvalNeverWritesOverTheGroundTruthDataset) {
  const fs::path ds = make_dataset(), run = make_run(ds);
  const auto before = listing(ds);
  for (const std::string& out : {ds.string(), ds.string() + "/", ds.string() + "/../ds"}) {
    for (const char* force : {"", " --force"}) {
      const auto r = wifislam("eval " + run.string() + " --gt " + ds.string() + " -o " + out +
                              force + " --no-plots");
      expect_refused(r, ds, "is an input of this command");
      EXPECT_EQ(listing(ds), before) << out << force;
    }
  }
  EXPECT_FALSE(fs::exists(ds.string() + ".partial"));
  EXPECT_EQ(wifislam("check " + ds.string()).exit_code, 0);
}

TEST_F(OutputFolders, EvalNeverWritesOverItsRunFolder) {
  const fs::path ds = make_dataset(), run = make_run(ds);
  const auto before = listing(run);
  for (const char* force : {"", " --force"}) {
    const auto r = wifislam("eval " + run.string() + " --gt " + ds.string() + " -o " +
                            run.string() + force + " --no-plots");
    expect_refused(r, run, "is an input of this command");
    EXPECT_EQ(listing(run), before);
  }
  // The folder holding both inputs is refused too.
  const auto r = wifislam("eval " + run.string() + " --gt " + ds.string() + " -o " +
                          work_.string() + " --force --no-plots");
  expect_refused(r, work_, "holds an input of this command");
}

TEST_F(OutputFolders, EvalNeverEmptiesTheCurrentDirectory) {
  const fs::path ds = make_dataset(), run = make_run(ds);
  const fs::path here = work_ / "here";
  test::write_file(here / "notes.txt", "my notes");
  for (const char* force : {"", " --force"}) {
    const auto r =
        wifislam("eval ../run --gt ../ds -o ." + std::string(force) + " --no-plots", here);
    expect_refused(r, here, "current directory");
    EXPECT_EQ(test::read_file(here / "notes.txt"), "my notes");
  }
  EXPECT_EQ(listing(here).size(), 1u);
}

TEST_F(OutputFolders, EvalReplacesItsOwnDefaultFolderButNoOtherWithoutForce) {
  const fs::path ds = make_dataset(), run = make_run(ds);
  for (int i = 0; i < 2; ++i) {
    const auto r = wifislam("eval " + run.string() + " --gt " + ds.string() + " --no-plots");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::is_regular_file(run / "eval" / "report.md"));
  }
  const fs::path other = work_ / "other_eval";
  fs::copy(run / "eval", other, fs::copy_options::recursive);
  auto r = wifislam("eval " + run.string() + " --gt " + ds.string() + " -o " + other.string() +
                    " --no-plots");
  expect_refused(r, other, "--force");
  r = wifislam("eval " + run.string() + " --gt " + ds.string() + " -o " + other.string() +
               " --force --no-plots");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(other / "report.md"));
}

TEST_F(OutputFolders, GenerateWithForceNeverEmptiesTheCurrentOrHomeDirectory) {
  const fs::path here = work_ / "here";
  test::write_file(here / "notes.txt", "my notes");
  auto r = wifislam("generate ../tiny.yaml -o . --force --fps 2 --max-frames 2 -q", here);
  expect_refused(r, here, "current directory");
  r = wifislam("generate ../tiny.yaml -o .. --force --fps 2 --max-frames 2 -q", here);
  expect_refused(r, work_, "holds");
  EXPECT_EQ(test::read_file(here / "notes.txt"), "my notes");
  EXPECT_EQ(listing(here).size(), 1u);

  // The home folder, made a scratch folder here so the test never goes near the real one.
  const fs::path home = work_ / "home";
  test::write_file(home / "notes.txt", "my notes");
  test::write_file(home / ".wifislam-output", "looks like output, still home");
  r = wifislam(
      "generate " + scene_.string() + " -o " + home.string() + " --force --fps 2 --max-frames 2 -q",
      {}, "HOME='" + home.string() + "'");
  expect_refused(r, home, "home folder");
  EXPECT_EQ(test::read_file(home / "notes.txt"), "my notes");
  EXPECT_FALSE(fs::exists(home.string() + ".partial"));
}

TEST_F(OutputFolders, ForceNeverReplacesAFolderThatIsNotThisToolsOutput) {
  const fs::path mine = user_folder("mine");
  const auto before = listing(mine);
  auto r = wifislam("generate " + scene_.string() + " -o " + mine.string() +
                    " --force --fps 2 --max-frames 2 -q");
  expect_refused(r, mine, "does not look like wifislam output");
  EXPECT_NE(r.err.find("even with --force"), std::string::npos) << r.err;
  EXPECT_EQ(listing(mine), before);
  EXPECT_FALSE(fs::exists(mine.string() + ".partial"));

  const fs::path ds = make_dataset();
  r = wifislam("slam " + ds.string() + " -o " + mine.string() + " --force");
  expect_refused(r, mine, "does not look like wifislam output");
  EXPECT_EQ(listing(mine), before);
}

// Issue 44, the data loss: a user's folder holding metrics.json + report.md (or comparison.json +
// comparison.md) was taken for an old eval (compare) report and `generate --force` deleted
// thesis.tex with it. Only the marker makes a folder replaceable now.
TEST_F(OutputFolders, ForceKeepsAUserFolderWhoseFileNamesLookLikeOurReports) {
  for (const auto& [report, text] :
       {std::pair{"metrics.json", "report.md"}, std::pair{"comparison.json", "comparison.md"}}) {
    const fs::path mine = user_folder(std::string("reports_") + report);
    test::write_file(mine / report, "{}\n");
    test::write_file(mine / text, "\n");
    const auto before = listing(mine);
    const auto r = wifislam("generate " + scene_.string() + " -o " + mine.string() +
                            " --force --no-images --fps 2 --max-frames 2 -q");
    expect_refused(r, mine, "does not look like wifislam output");
    EXPECT_EQ(listing(mine), before);
    EXPECT_FALSE(fs::exists(mine.string() + ".partial"));
  }
}

TEST_F(OutputFolders, AnEmptyFolderIsReplacedWithForceOnly) {
  const fs::path empty = work_ / "empty";
  fs::create_directories(empty);
  auto r = wifislam("generate " + scene_.string() + " -o " + empty.string() +
                    " --fps 2 --max-frames 2 -q");
  expect_refused(r, empty, "already exists (pass --force to replace it)");
  r = wifislam("generate " + scene_.string() + " -o " + empty.string() +
               " --fps 2 --max-frames 2 -q --force");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(empty / "manifest.json"));
  // And the dataset it holds now is this tool's output: --force replaces it again.
  r = wifislam("generate " + scene_.string() + " -o " + empty.string() +
               " --fps 2 --max-frames 3 -q --force");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(empty.string() + ".replaced"));
}

TEST_F(OutputFolders, NoCommandReplacesItsOwnInput) {
  const fs::path ds = make_dataset();
  auto r = wifislam("slam " + ds.string() + " -o " + ds.string() + " --force");
  expect_refused(r, ds, "is an input of this command");
  EXPECT_EQ(wifislam("check " + ds.string()).exit_code, 0);
  // A folder of outputs that also holds the scene file being read.
  const fs::path scenes = work_ / "scenes";
  test::write_file(scenes / "tiny.yaml", test::kTinyLoopYaml);
  test::write_file(scenes / ".wifislam-output", "");
  r = wifislam("generate " + (scenes / "tiny.yaml").string() + " -o " + scenes.string() +
               " --force --fps 2 --max-frames 2 -q");
  expect_refused(r, scenes, "holds an input of this command");
  EXPECT_TRUE(fs::is_regular_file(scenes / "tiny.yaml"));
  // Single-file outputs never overwrite the scene they draw.
  r = wifislam("world " + scene_.string() + " --plan " + scene_.string());
  expect_refused(r, scene_, "is an input of this command");
  r = wifislam("radiomap " + scene_.string() + " --strongest -o " + scene_.string());
  expect_refused(r, scene_, "is an input of this command");
  EXPECT_EQ(test::read_file(scene_), test::kTinyLoopYaml);
  // `--plan X.png --svg` writes X.svg too: both are checked before either is written (the PNG
  // was written, then X.svg, the scene, refused).
  const fs::path svg_scene = work_ / "plan.svg", png = work_ / "plan.png";
  test::write_file(svg_scene, test::kTinyLoopYaml);
  r = wifislam("world " + svg_scene.string() + " --plan " + png.string() + " --svg");
  expect_refused(r, svg_scene, "is an input of this command");
  EXPECT_FALSE(fs::exists(png));
  EXPECT_EQ(test::read_file(svg_scene), test::kTinyLoopYaml);
}

// Inputs named by options or inside other files, and outputs of other commands: a vocabulary
// and training file given to `localize`, a scene a study file names (`study slurm`), a dataset
// given to `paper -o` (a paper folder only), and a file written into an input dataset (`vocab`).
TEST_F(OutputFolders, ForceNeverReplacesWhatAnotherOptionOrFileReads) {
  const fs::path ds = make_dataset();
  // localize: the output folder (a dataset of ours, so --force could replace it) holds the
  // vocabulary and training files given; they are checked as inputs before anything is read.
  test::write_file(ds / "my.bin", "vocabulary");
  test::write_file(ds / "my.fabmap", "training");
  auto r =
      wifislam("localize " + scene_.string() + " --vocabulary " + (ds / "my.bin").string() +
               " --training " + (ds / "my.fabmap").string() + " -o " + ds.string() + " --force");
  expect_refused(r, ds, "holds an input of this command");
  EXPECT_EQ(test::read_file(ds / "my.bin"), "vocabulary");
  fs::remove(ds / "my.bin");
  fs::remove(ds / "my.fabmap");
  // study slurm: the job folder (ours) holds the scene the study file names.
  const fs::path job = work_ / "job";
  test::write_file(job / "scene.yaml", test::kTinyLoopYaml);
  test::write_file(job / ".wifislam-output", "");
  const fs::path study = work_ / "s.yaml";
  test::write_file(study,
                   "version: 1\nname: s\nscene: job/scene.yaml\nlevel: radio\naxes:\n"
                   "  seed: [1, 2]\n");
  r = wifislam("study slurm " + study.string() + " --tasks 1 -o " + job.string() + " --force");
  expect_refused(r, job, "holds an input of this command");
  EXPECT_TRUE(fs::is_regular_file(job / "scene.yaml"));
  // paper --force: a dataset is not a paper folder, marker or not.
  r = wifislam("paper -o " + ds.string() + " --force --parts fabmap --twins c_hall");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("not a paper folder"), std::string::npos) << r.err;
  EXPECT_EQ(wifislam("check " + ds.string()).exit_code, 0);
  // vocab train: a file written into the dataset it reads would break the dataset's manifest.
  r = wifislam("vocab train " + ds.string() + " --every 1 -o " + (ds / "groundtruth.txt").string() +
               " --force");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("lies inside an input of this command"), std::string::npos) << r.err;
  EXPECT_EQ(wifislam("check " + ds.string()).exit_code, 0);
}

// A run reads files an option names too: the ORB vocabulary (`--set` or `--sweep vocabulary=`)
// and an external system's file (`--frontend external:FILE`). `--force` onto a run folder that
// holds one deleted it with the folder and exited 0.
TEST_F(OutputFolders, ForceNeverReplacesAFolderHoldingAVocabularyOrSystemFileARunReads) {
  const fs::path ds = make_dataset();
  const fs::path run = make_run(ds);
  test::write_file(run / "my.bin", "vocabulary");
  test::write_file(run / "my_system.yaml", "system");
  const std::string vocabulary = (run / "my.bin").string();
  for (const std::string& command :
       {"slam " + ds.string() + " --frontend orbslam --set vocabulary=" + vocabulary,
        "slam " + ds.string() + " --frontend external:" + (run / "my_system.yaml").string(),
        "compare " + scene_.string() + " --fps 2 --max-frames 6 --frontend orbslam --set " +
            "vocabulary=" + vocabulary,
        "compare " + scene_.string() + " --fps 2 --max-frames 6 --frontend orbslam --sweep " +
            "orb_levels=4,8 --sweep vocabulary=" + vocabulary + "," + vocabulary + ".other"}) {
    SCOPED_TRACE(command);
    expect_refused(wifislam(command + " -o " + run.string() + " --force"), run,
                   "holds an input of this command");
    EXPECT_EQ(test::read_file(run / "my.bin"), "vocabulary");
    EXPECT_EQ(test::read_file(run / "my_system.yaml"), "system");
  }
}

// The demo's own folder (./demo-output) is replaced on every run, so scripts/demo.sh runs twice
// in a row; another existing folder needs --force. A very short route keeps the demo quick; its
// pauses are long enough for a Wi-Fi scan (the tiny loop's 1 s are not), which the demo's Wi-Fi
// run needs.
TEST_F(OutputFolders, DemoRunsTwiceInARowIntoItsOwnFolder) {
  std::string yaml = test::kTinyLoopYaml;
  yaml.replace(yaml.find("nodes: [A, B, C, D, A]"), 22, "nodes: [A, B]");
  yaml.replace(yaml.find("duration_s: 1.0"), 15, "duration_s: 5.0");
  yaml += "sensors: {camera: {fps: 1.0}}\n";
  test::write_file(work_ / "short.yaml", yaml);
  for (int i = 0; i < 2; ++i) {
    const auto r = wifislam("demo --scene short.yaml -q", work_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::is_regular_file(work_ / "demo-output" / "comparison.md"));
  }
  fs::copy(work_ / "demo-output", work_ / "mine", fs::copy_options::recursive);
  auto r = wifislam("demo --scene short.yaml -q -o mine", work_);
  expect_refused(r, work_ / "mine", "--force");
  fs::create_directories(work_ / "sub");
  r = wifislam("demo --scene ../short.yaml -q -o .", work_ / "sub");
  expect_refused(r, work_ / "sub", "current directory");
  EXPECT_TRUE(fs::is_regular_file(work_ / "short.yaml"));
}

}  // namespace
}  // namespace wifislam
