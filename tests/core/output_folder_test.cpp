// The output-folder rule (core/output_folder.hpp) on real folders in a temporary directory: what
// may be replaced, what never is, and that paths are compared after resolving them.
#include <gtest/gtest.h>

#include <pwd.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;

class OutputFolderRule : public ::testing::Test {
 protected:
  void SetUp() override { root_ = test::scratch_folder(); }
  void TearDown() override {
    fs::remove_all(root_);
    fs::remove_all(root_.string() + ".partial");
  }
  // A folder as this tool leaves it (marker file) with one more file in it.
  fs::path tool_folder(const std::string& name) {
    const fs::path dir = root_ / name;
    fs::create_directories(dir);
    std::ofstream(dir / kOutputMarkerFile) << "x";
    std::ofstream(dir / "data.txt") << "data";
    return dir;
  }
  fs::path user_folder(const std::string& name) {
    const fs::path dir = root_ / name;
    fs::create_directories(dir);
    std::ofstream(dir / "thesis.tex") << "years of work";
    return dir;
  }
  // The message of the refusal, or nullopt when the request is accepted.
  static std::optional<std::string> refusal(const OutputFolderRequest& request) {
    try {
      check_output_folder(request);
      return std::nullopt;
    } catch (const InvalidInputError& e) {
      return std::string(e.what());
    }
  }
  fs::path root_;
};

TEST_F(OutputFolderRule, NewFolderNeedsNothing) {
  EXPECT_FALSE(check_output_folder({root_ / "new", false, {}, {}}));
}

TEST_F(OutputFolderRule, ExistingOutputOfThisToolIsReplacedOnlyWithForce) {
  const fs::path out = tool_folder("out");
  const auto message = refusal({out, false, {}, {}});
  ASSERT_TRUE(message);
  EXPECT_NE(message->find(out.string()), std::string::npos) << *message;
  EXPECT_NE(message->find("--force"), std::string::npos) << *message;
  EXPECT_TRUE(check_output_folder({out, true, {}, {}}));
}

// Issue 44: `generate -o u --force` deleted u/thesis.tex because u also held metrics.json and
// report.md, which a fallback took for an old eval report. Only the marker makes a folder ours:
// file names that look like ours, even with this tool's "format" inside, are no proof.
TEST_F(OutputFolderRule, OnlyTheMarkerMakesAFolderReplaceable) {
  const std::vector<std::vector<std::pair<std::string, std::string>>> look_alikes = {
      {{"metrics.json", "{}"}, {"report.md", "\n"}},
      {{"comparison.json", "{}"}, {"comparison.md", "\n"}},
      {{"manifest.json", R"({"format": "wifislam-dataset"})"}},
      {{"run.json", R"({"format": "wifislam-run", "format_version": 2})"}},
  };
  int index = 0;
  for (const auto& files : look_alikes) {
    const fs::path dir = user_folder("look_alike_" + std::to_string(index++));
    for (const auto& [name, text] : files) std::ofstream(dir / name) << text;
    EXPECT_FALSE(has_output_marker(dir)) << dir;
    const auto message = refusal({dir, true, {}, {}});
    ASSERT_TRUE(message) << dir;
    EXPECT_NE(message->find("does not look like wifislam output"), std::string::npos) << *message;
    EXPECT_NE(message->find(kOutputMarkerFile), std::string::npos) << *message;
    EXPECT_TRUE(fs::exists(dir / "thesis.tex"));
    // With the marker the same folder is ours.
    std::ofstream(dir / kOutputMarkerFile) << "x";
    EXPECT_TRUE(has_output_marker(dir));
    EXPECT_TRUE(check_output_folder({dir, true, {}, {}}));
  }
  // A folder named like the marker is not the marker.
  const fs::path odd = user_folder("odd");
  fs::create_directories(odd / kOutputMarkerFile);
  EXPECT_FALSE(has_output_marker(odd));
  EXPECT_TRUE(refusal({odd, true, {}, {}}));
}

TEST_F(OutputFolderRule, UserFolderIsRefusedEvenWithForceButAnEmptyOneIsNot) {
  const fs::path mine = user_folder("mine");
  const auto message = refusal({mine, true, {}, {}});
  ASSERT_TRUE(message);
  EXPECT_NE(message->find(mine.string()), std::string::npos) << *message;
  EXPECT_NE(message->find("even with --force"), std::string::npos) << *message;
  EXPECT_TRUE(fs::exists(mine / "thesis.tex"));
  fs::create_directories(root_ / "empty");
  EXPECT_TRUE(check_output_folder({root_ / "empty", true, {}, {}}));
}

TEST_F(OutputFolderRule, OwnedDefaultIsReplacedWithoutForceEvenInsideItsInput) {
  const fs::path run = tool_folder("run");
  const fs::path eval = tool_folder("run/eval");
  EXPECT_TRUE(check_output_folder({eval, false, eval, {run}, run}));
  // The same folder spelt differently is still the default.
  EXPECT_TRUE(check_output_folder({root_ / "run/./eval/", false, eval, {run}, run}));
  // Not the default: inside an input, refused even with --force.
  const fs::path other = tool_folder("run/other");
  const auto message = refusal({other, true, eval, {run}, run});
  ASSERT_TRUE(message);
  EXPECT_NE(message->find("inside an input"), std::string::npos) << *message;
}

// `eval ds/groundtruth.txt --gt ds`: the default <file>_eval would lie inside the dataset, an input
// that does not own it. Refused, named or not, with or without --force.
TEST_F(OutputFolderRule, TheDefaultLiesOnlyInsideTheInputThatOwnsIt) {
  const fs::path ds = tool_folder("ds");
  const fs::path trajectory = ds / "groundtruth.txt";
  std::ofstream(trajectory) << "1 0 0 0 0 0 0 1\n";
  const fs::path default_out = ds / "groundtruth_eval";
  for (const bool force : {false, true}) {
    const auto message = refusal({default_out, force, default_out, {trajectory, ds}, {}});
    ASSERT_TRUE(message);
    EXPECT_NE(message->find("inside an input"), std::string::npos) << *message;
    EXPECT_NE(message->find(ds.string()), std::string::npos) << *message;
  }
  EXPECT_FALSE(fs::exists(default_out));
  // Inside the run folder that owns it, not inside another input.
  const fs::path run = tool_folder("ds_run");
  EXPECT_FALSE(check_output_folder({run / "eval", false, run / "eval", {run, ds}, run}));
  EXPECT_TRUE(refusal({run / "eval", false, run / "eval", {run, ds}, ds}));
}

// Issue 34: a new folder inside an input replaced nothing, so it passed (`slam ds -o ds/run`
// wrote the run into the dataset); only export asked for the refusal. It is the rule for every
// command now, with or without --force; the owned default (eval's <run>/eval) is the exception.
TEST_F(OutputFolderRule, ANewFolderInsideAnInputIsRefused) {
  const fs::path ds = tool_folder("ds");
  for (const bool force : {false, true}) {
    const auto message = refusal({ds / "run", force, {}, {ds}});
    ASSERT_TRUE(message);
    EXPECT_NE(message->find("inside an input"), std::string::npos) << *message;
    EXPECT_NE(message->find(ds.string()), std::string::npos) << *message;
  }
  EXPECT_FALSE(fs::exists(ds / "run"));
  // Spelt through `..` it is the same folder.
  EXPECT_TRUE(refusal({root_ / "x" / ".." / "ds" / "deep" / "run", false, {}, {ds}}));
  EXPECT_FALSE(check_output_folder({root_ / "beside", false, {}, {ds}}));
  const fs::path run = tool_folder("run");
  EXPECT_FALSE(check_output_folder({run / "eval-new", false, run / "eval-new", {run}, run}));
}

TEST_F(OutputFolderRule, AnInputOrAFolderHoldingOneIsNeverReplaced) {
  const fs::path ds = tool_folder("ds");
  const fs::path run = tool_folder("run");
  for (const fs::path& out : {ds, run, root_}) {
    const auto message = refusal({out, true, run / "eval", {run, ds}});
    ASSERT_TRUE(message) << out;
    EXPECT_NE(message->find("input"), std::string::npos) << *message;
  }
  const fs::path scene = root_ / "scenes" / "a.yaml";
  fs::create_directories(scene.parent_path());
  std::ofstream(scene) << "version: 1\n";
  std::ofstream(root_ / "scenes" / kOutputMarkerFile) << "x";
  EXPECT_TRUE(refusal({root_ / "scenes", true, {}, {scene}}));
}

TEST_F(OutputFolderRule, PathsAreComparedAfterResolvingSymlinksDotsAndSlashes) {
  const fs::path ds = tool_folder("ds");
  fs::create_directory_symlink(ds, root_ / "link");
  for (const fs::path& spelling :
       {root_ / "link", root_ / "ds/", root_ / "ds/../ds", root_ / "link/./"}) {
    EXPECT_TRUE(refusal({spelling, true, {}, {ds}})) << spelling;
    EXPECT_TRUE(refusal({ds, true, {}, {spelling}})) << spelling;
  }
}

// A link at eval's default <run>/eval to a dataset: replacing the default emptied the dataset,
// without --force. A symbolic link is never an output folder, default or named, with or without
// --force, dangling or not; the folder it points to is left as it was.
TEST_F(OutputFolderRule, ASymbolicLinkIsNeverReplacedNorWrittenThrough) {
  const fs::path run = tool_folder("run");
  const fs::path victim = tool_folder("victim");
  fs::create_directory_symlink(victim, run / "eval");
  for (const bool force : {false, true}) {
    for (const fs::path& spelling :
         {run / "eval", fs::path(run.string() + "/eval/"), fs::path(run.string() + "/eval/."),
          fs::path(run.string() + "/eval/./")}) {
      const auto message = refusal({spelling, force, run / "eval", {run}, run});
      ASSERT_TRUE(message) << spelling;
      EXPECT_NE(message->find("symbolic link"), std::string::npos) << *message;
      EXPECT_NE(message->find(victim.string()), std::string::npos) << *message;
    }
  }
  fs::create_directory_symlink(root_ / "nowhere", root_ / "dangling");
  EXPECT_TRUE(refusal({root_ / "dangling", false, {}, {}}));
  EXPECT_TRUE(fs::exists(victim / "data.txt"));
  // A link above the folder is only a way to spell its path.
  fs::create_directory_symlink(root_, root_ / "up");
  EXPECT_TRUE(check_output_folder({root_ / "up" / "victim", true, {}, {}}));
}

TEST_F(OutputFolderRule, CurrentDirectoryItsParentsTheHomeFolderAndRootAreNeverReplaced) {
  const fs::path work = tool_folder("work");
  const fs::path inner = tool_folder("work/inner");
  const fs::path saved = fs::current_path();
  fs::current_path(inner);
  for (const fs::path& out : {fs::path("."), fs::path(".."), inner, work}) {
    const auto message = refusal({out, true, {}, {}});
    ASSERT_TRUE(message) << out;
    EXPECT_NE(message->find("current directory"), std::string::npos) << *message;
  }
  fs::current_path(saved);

  const char* home_before = std::getenv("HOME");
  const std::string saved_home = home_before ? home_before : "";
  ::setenv("HOME", inner.c_str(), 1);
  const auto message = refusal({work, true, {}, {}});
  if (home_before) {
    ::setenv("HOME", saved_home.c_str(), 1);
  } else {
    ::unsetenv("HOME");
  }
  ASSERT_TRUE(message);
  EXPECT_NE(message->find("home folder"), std::string::npos) << *message;

  // With HOME unset (or pointing elsewhere), the password database's home is still protected.
  if (const passwd* user = ::getpwuid(::getuid()); user && user->pw_dir && *user->pw_dir) {
    ::unsetenv("HOME");
    const auto passwd_message = refusal({user->pw_dir, true, {}, {}});
    if (home_before) ::setenv("HOME", saved_home.c_str(), 1);
    ASSERT_TRUE(passwd_message);
    EXPECT_NE(passwd_message->find("home folder"), std::string::npos) << *passwd_message;
  }

  const auto root_message = refusal({"/", true, {}, {}});
  ASSERT_TRUE(root_message);
  EXPECT_NE(root_message->find("root"), std::string::npos) << *root_message;
}

TEST_F(OutputFolderRule, AFileIsNotAFolderToReplace) {
  std::ofstream(root_ / "notes.txt") << "notes";
  EXPECT_TRUE(refusal({root_ / "notes.txt", true, {}, {}}));
  EXPECT_TRUE(fs::exists(root_ / "notes.txt"));
}

TEST_F(OutputFolderRule, OutputFileMustNotBeAnInputOrAFolder) {
  const fs::path scene = root_ / "scene.yaml";
  std::ofstream(scene) << "version: 1\n";
  EXPECT_THROW(check_output_file(root_ / "./scene.yaml", {scene}), InvalidInputError);
  EXPECT_THROW(check_output_file(root_, {scene}), InvalidInputError);
  EXPECT_NO_THROW(check_output_file(root_ / "plan.png", {scene}));
  // An existing file of the user's that is not an input may be replaced.
  std::ofstream(root_ / "old.png") << "old";
  EXPECT_NO_THROW(check_output_file(root_ / "old.png", {scene}));
}

// Two outputs of one command that are one file: the second would overwrite the first.
TEST_F(OutputFolderRule, TwoOutputsThatAreOneFileAreRefusedNamingBoth) {
  const fs::path scene = root_ / "scene.yaml";
  std::ofstream(scene) << "version: 1\n";
  try {
    check_output_files({root_ / "fit.yaml", {}, root_ / "sub" / ".." / "fit.yaml"}, {scene});
    ADD_FAILURE() << "two outputs naming one file were accepted";
  } catch (const InvalidInputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("is also given as " + (root_ / "fit.yaml").string()), std::string::npos)
        << message;
    EXPECT_EQ(message.find("is an input"), std::string::npos) << message;
  }
  EXPECT_NO_THROW(check_output_files({root_ / "fit.yaml", {}, root_ / "fit.md"}, {scene}));
  // Each output is still checked on its own.
  EXPECT_THROW(check_output_files({root_ / "fit.yaml", scene}, {scene}), InvalidInputError);
}

// The rename of <file>.partial would put a regular file where a pipe or device was (as root, over
// /dev/null): refused before any work, the pipe left as it was.
TEST_F(OutputFolderRule, OutputFileMustNotBeAPipeOrDevice) {
  const fs::path fifo = root_ / "pipe.png";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const fs::path& target : {fifo, fs::path("/dev/null")}) {
    try {
      check_output_file(target, {});
      ADD_FAILURE() << target << " accepted";
    } catch (const InvalidInputError& e) {
      EXPECT_NE(std::string(e.what()).find("a device, pipe or socket"), std::string::npos)
          << e.what();
    }
    EXPECT_THROW(check_file_replaceable(target), InvalidInputError);
  }
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

// A command writing two files (radiomap's PNG and --csv) checks both before writing either: a
// missing folder is found before the work, not after the first file replaced the user's.
TEST_F(OutputFolderRule, OutputFileInAMissingFolderIsAnIoErrorBeforeAnyWork) {
  EXPECT_THROW(check_output_file(root_ / "missing" / "map.csv", {}), IoError);
  std::ofstream(root_ / "file") << "x";
  EXPECT_THROW(check_output_file(root_ / "file" / "map.csv", {}), InvalidInputError);
}

TEST_F(OutputFolderRule, AtomicDirectoryMarksItsFolderAndKeepsUserFolders) {
  const fs::path out = root_ / "out";
  {
    AtomicDirectory dir(out, false);
    std::ofstream(dir.staging_path() / "a.txt") << "a";
    dir.commit();
  }
  EXPECT_TRUE(fs::is_regular_file(out / kOutputMarkerFile));
  EXPECT_TRUE(has_output_marker(out));
  {
    AtomicDirectory dir(out, true);  // its own output: replaced
    std::ofstream(dir.staging_path() / "b.txt") << "b";
    dir.commit();
  }
  EXPECT_FALSE(fs::exists(out / "a.txt"));
  EXPECT_TRUE(fs::exists(out / "b.txt"));
  EXPECT_FALSE(fs::exists(out.string() + ".replaced"));

  const fs::path mine = user_folder("mine");
  EXPECT_THROW(AtomicDirectory(mine, true), InvalidInputError);
  EXPECT_TRUE(fs::exists(mine / "thesis.tex"));
  EXPECT_FALSE(fs::exists(mine.string() + ".partial"));
}

// Only a staging folder (it holds the unfinished marker until its commit) is a leftover to
// remove. A finished output named `<out>.partial` was deleted by a run into `<out>`, without
// --force; and `<out>.replaced` by a --force run, whatever it held.
TEST_F(OutputFolderRule, FoldersBesideTheOutputAreRemovedOnlyWhenARunLeftThem) {
  const fs::path out = root_ / "exp";
  {
    AtomicDirectory finished(root_ / "exp.partial", false);  // a user's `-o exp.partial`
    EXPECT_TRUE(has_unfinished_marker(finished.staging_path()));
    finished.commit();
  }
  const fs::path named_partial = root_ / "exp.partial";
  EXPECT_TRUE(has_output_marker(named_partial));
  EXPECT_FALSE(has_unfinished_marker(named_partial)) << "a finished output is not unfinished";
  std::ofstream(named_partial / "notes.txt") << "mine";
  try {
    AtomicDirectory refused(out, false);
    ADD_FAILURE() << "a finished output named exp.partial was taken for a leftover";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("holds a finished output"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::exists(named_partial / "notes.txt"));
  EXPECT_FALSE(fs::exists(out));
  // Commands say so before their work (a slam run writes its folder only at the end).
  EXPECT_TRUE(refusal({out, false, {}, {}}));

  // What an interrupted run leaves (both markers) is removed by the next run, as before.
  fs::remove_all(named_partial);
  fs::create_directories(named_partial);
  std::ofstream(named_partial / kOutputMarkerFile) << "x";
  std::ofstream(named_partial / kUnfinishedMarkerFile) << "x";
  std::ofstream(named_partial / "half.png") << "half";
  {
    AtomicDirectory dir(out, false);
    EXPECT_FALSE(fs::exists(dir.staging_path() / "half.png"));
    dir.commit();
  }
  EXPECT_FALSE(has_unfinished_marker(out));

  // `<out>.replaced` is where --force sets the old folder aside: one that is there already is
  // kept, and the replacement refused before the work, or at the commit if it came since.
  const fs::path replaced = tool_folder("exp.replaced");
  EXPECT_THROW(AtomicDirectory(out, true), InvalidInputError);
  EXPECT_TRUE(refusal({out, true, {}, {}}));
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
  fs::rename(replaced, root_ / "elsewhere");
  {
    AtomicDirectory dir(out, true);
    std::ofstream(dir.staging_path() / "new.txt") << "new";
    fs::rename(root_ / "elsewhere", replaced);
    EXPECT_THROW(dir.commit(), InvalidInputError);
  }
  EXPECT_TRUE(fs::exists(replaced / "data.txt"));
  EXPECT_TRUE(has_output_marker(out));
  EXPECT_FALSE(fs::exists(out / "new.txt"));
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
  fs::remove_all(replaced);
  fs::create_directories(replaced);  // empty: nothing to lose, removed
  {
    AtomicDirectory dir(out, true);
    std::ofstream(dir.staging_path() / "new.txt") << "new";
    dir.commit();
  }
  EXPECT_TRUE(fs::exists(out / "new.txt"));
  EXPECT_FALSE(fs::exists(replaced));

  // A deletion of the set-aside folder that a second Ctrl-C cut short left its marker (deleted
  // last) and some of the old output: the next replacement finishes it.
  fs::create_directories(replaced / "rgb");
  std::ofstream(replaced / "rgb" / "1.png") << "old";
  std::ofstream(replaced / kDiscardedMarkerFile) << "x";
  EXPECT_FALSE(refusal({out, true, {}, {}}));
  {
    AtomicDirectory dir(out, true);
    std::ofstream(dir.staging_path() / "newer.txt") << "newer";
    dir.commit();
  }
  EXPECT_TRUE(fs::exists(out / "newer.txt"));
  EXPECT_FALSE(fs::exists(replaced));
}

// Folders of ours are removed with their marker last (so that a removal a kill cuts short leaves
// a folder still known as ours); nested folders and all, nothing stays. A link is not followed.
TEST_F(OutputFolderRule, AFolderOfOursIsRemovedWithEverythingInIt) {
  const fs::path dir = root_ / "left";
  for (const char* name : {"a", "b", "rgb/1.png", "rgb/2.png", "z"}) {
    fs::create_directories((dir / name).parent_path());
    std::ofstream(dir / name) << name;
  }
  std::ofstream(dir / kUnfinishedMarkerFile) << "x";
  const fs::path link = root_ / "link";
  fs::create_directory_symlink(dir, link);
  remove_folder_marker_last(link, kUnfinishedMarkerFile);  // the link only
  EXPECT_FALSE(fs::exists(fs::symlink_status(link)));
  EXPECT_TRUE(fs::exists(dir / "rgb" / "1.png"));
  remove_folder_marker_last(dir, kUnfinishedMarkerFile);
  EXPECT_FALSE(fs::exists(dir));
}

// Every writer of a folder goes through AtomicDirectory, not only the commands that check their
// output first: an external system that left `eval` in its run folder as a link to a finished
// output of ours made the evaluation replace that output.
TEST_F(OutputFolderRule, AtomicDirectoryNeverReplacesAFolderThroughALink) {
  const fs::path victim = tool_folder("victim");
  fs::create_directory_symlink(victim, root_ / "eval");
  for (const fs::path& spelling : {root_ / "eval", fs::path(root_.string() + "/eval/."),
                                   fs::path(root_.string() + "/eval/")}) {
    try {
      AtomicDirectory refused(spelling, true);
      ADD_FAILURE() << spelling << " was written through";
    } catch (const InvalidInputError& e) {
      EXPECT_NE(std::string(e.what()).find("symbolic link"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(fs::exists(victim / "data.txt"));
  EXPECT_FALSE(fs::exists(victim.string() + ".partial"));
}

// A run stopped between its last two steps leaves its finished output in <out>.partial without
// the unfinished marker: the refusal says what it is and what to do, not "a folder of yours".
TEST_F(OutputFolderRule, AFinishedOutputNeverMovedIntoPlaceIsNamedAsSuch) {
  const fs::path out = root_ / "ds";
  tool_folder("ds.partial");
  const auto message = refusal({out, false, {}, {}});
  ASSERT_TRUE(message);
  EXPECT_NE(message->find("never moved into place"), std::string::npos) << *message;
  EXPECT_NE(message->find("rename it to " + out.string()), std::string::npos) << *message;
  EXPECT_TRUE(fs::exists(root_ / "ds.partial" / "data.txt"));
  // A folder of the user's by that name (no output marker) is named as what it may be.
  fs::remove_all(root_ / "ds.partial");
  user_folder("ds.partial");
  const auto user = refusal({out, false, {}, {}});
  ASSERT_TRUE(user);
  EXPECT_NE(user->find("a folder of yours"), std::string::npos) << *user;
  EXPECT_TRUE(fs::exists(root_ / "ds.partial" / "thesis.tex"));
}

// The folders beside an output that a run may remove never hold an input or the current folder:
// `slam ds.partial --no-verify -o ds` read a leftover dataset and then removed it as a leftover.
TEST_F(OutputFolderRule, FoldersBesideTheOutputNeverHoldAnInputOrTheCurrentFolder) {
  const fs::path leftover = root_ / "ds.partial";
  fs::create_directories(leftover);
  std::ofstream(leftover / kUnfinishedMarkerFile) << "x";
  std::ofstream(leftover / "rgb.txt") << "frames";
  const auto message = refusal({root_ / "ds", false, {}, {leftover}});
  ASSERT_TRUE(message);
  EXPECT_NE(message->find("holds an input"), std::string::npos) << *message;
  EXPECT_TRUE(refusal({root_ / "ds", false, {}, {leftover / "rgb.txt"}}));
  const fs::path before = fs::current_path();
  fs::current_path(leftover);
  const auto from_inside = refusal({root_ / "ds", false, {}, {}});
  EXPECT_THROW(AtomicDirectory(root_ / "ds", false), InvalidInputError);
  fs::current_path(before);
  ASSERT_TRUE(from_inside);
  EXPECT_NE(from_inside->find("run it from elsewhere"), std::string::npos) << *from_inside;
  EXPECT_TRUE(fs::exists(leftover / "rgb.txt"));
}

// A folder another run is writing (its staging folder, named as an output with --force) is not
// replaced: that run lost its folder and failed with "write failed (disk full?)".
TEST_F(OutputFolderRule, AnotherRunsStagingFolderIsNeverReplaced) {
  AtomicDirectory other(root_ / "ds", false);
  std::ofstream(other.staging_path() / "frame.png") << "png";
  const auto message = refusal({other.staging_path(), true, {}, {}});
  ASSERT_TRUE(message);
  EXPECT_NE(message->find("another wifislam run is writing"), std::string::npos) << *message;
  EXPECT_THROW(AtomicDirectory(other.staging_path(), true), InvalidInputError);
  EXPECT_TRUE(fs::exists(other.staging_path() / "frame.png"));
  other.commit();
  EXPECT_TRUE(fs::exists(root_ / "ds" / "frame.png"));
}

}  // namespace
}  // namespace wifislam
