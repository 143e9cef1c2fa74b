// Running studies into SQLite: a killed run resumes to the rows of an uninterrupted one, shards
// merge to the unsharded run, databases of another study are refused, and the radio level tells
// scattered access points from co-linear ones.
#include <gtest/gtest.h>

#include <algorithm>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>

#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "study/result_store.hpp"
#include "study/study_file.hpp"
#include "study/study_runner.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"
#include "tests/support/wait_until.hpp"

namespace wifislam::study {
namespace {

namespace fs = std::filesystem;

const std::string kScene = std::string(WIFISLAM_SCENES_DIR) + "/c_hall.yaml";

fs::path write_study(const fs::path& dir, const std::string& name, const std::string& axes) {
  const fs::path path = dir / (name + ".yaml");
  test::write_file(
      path, "version: 1\nname: " + name + "\nscene: " + kScene + "\nlevel: radio\naxes:\n" + axes);
  return path;
}

std::int64_t rows_in(const fs::path& db) {
  try {
    return static_cast<std::int64_t>(dump_results(db).size());
  } catch (const Error&) {
    return 0;  // not created yet, or its tables not yet committed
  }
}

TEST(StudyRun, AKilledRunResumesToTheRowsOfAnUninterruptedRun) {
  const fs::path dir = test::scratch_folder();
  // 40 radio cases of about 0.1 s each on c_hall.
  const fs::path file =
      write_study(dir, "resume",
                  "  access_points.count: [8, 16, 24, 32]\n  seed: [1, 2, 3, 4, 5, "
                  "6, 7, 8, 9, 10]\n");
  const fs::path whole = dir / "whole.sqlite", killed = dir / "killed.sqlite";
  ASSERT_EQ(
      test::run_wifislam("study run " + file.string() + " -q -o " + whole.string(), dir).exit_code,
      0);
  const std::int64_t total = rows_in(whole);
  ASSERT_EQ(total, 40);

  // The same study, killed with SIGKILL once a few cases are in.
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::execl(WIFISLAM_BINARY, WIFISLAM_BINARY, "study", "run", file.c_str(), "-q", "-o",
            killed.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  test::wait_until(
      std::chrono::seconds(120), [&] { return rows_in(killed) >= 3; },
      std::chrono::milliseconds(5));
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it could be killed";
  const std::int64_t at_kill = rows_in(killed);
  EXPECT_GE(at_kill, 3);
  EXPECT_LT(at_kill, total) << "every case was done before the kill: the test proves nothing";

  // The rerun skips the finished cases and ends with exactly the uninterrupted run's rows.
  const auto rerun =
      test::run_wifislam("study run " + file.string() + " -o " + killed.string(), dir);
  ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
  EXPECT_NE(rerun.err.find(std::to_string(at_kill) + " of 40 cases already in"), std::string::npos)
      << rerun.err;
  EXPECT_EQ(dump_results(killed), dump_results(whole));
  fs::remove_all(dir);
}

// A SLAM-level case runs in <database>.work/<case id>, and a rerun removes what a killed attempt
// left there; a folder of that name that the tool did not make is refused, not deleted.
TEST(StudyRun, AFolderOfTheUsersWhereACaseRunsIsRefusedNotDeleted) {
  const fs::path dir = test::scratch_folder();
  test::write_file(dir / "tiny.yaml", test::kTinyLoopYaml);
  const fs::path file = dir / "one_case.yaml";
  test::write_file(file,
                   "version: 1\nname: one_case\nscene: tiny.yaml\nlevel: slam\n"
                   "set: {route.pause.duration_s: 10}\n"
                   "axes:\n  seed: [1]\nslam: {fps: 1}\n");
  const std::vector<StudyCase> cases = shard_cases(load_study_file(file), 0, 1);
  ASSERT_EQ(cases.size(), 1u);
  const fs::path db = dir / "study.sqlite";
  const fs::path users = fs::path(db.string() + ".work") / cases[0].id;
  test::write_file(users / "mine.txt", "my notes");
  const auto refused =
      test::run_wifislam("study run " + file.string() + " -q -o " + db.string(), dir);
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("not made by wifislam"), std::string::npos) << refused.err;
  EXPECT_TRUE(fs::exists(users / "mine.txt"));

  // Once the folder is the tool's (a killed attempt's, with its marker), the run replaces it.
  fs::remove(users / "mine.txt");
  test::write_file(users / kOutputMarkerFile, "study case scratch folder\n");
  test::write_file(users / "partial.txt", "left by a killed attempt");
  const auto run = test::run_wifislam("study run " + file.string() + " -q -o " + db.string(), dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(rows_in(db), 2);  // vanilla and Wi-Fi
  EXPECT_FALSE(fs::exists(users));
  fs::remove_all(dir);
}

TEST(StudyRun, ShardsMergeToTheUnshardedRunAndForeignDatabasesAreRefused) {
  const fs::path dir = test::scratch_folder();
  const fs::path file =
      write_study(dir, "shards", "  access_points.count: [10, 20]\n  seed: [1, 2, 3]\n");
  const StudyFile study = load_study_file(file);
  StudyRunOptions whole;
  whole.database = dir / "whole.sqlite";
  run_study(study, whole);
  std::vector<fs::path> shards;
  for (int i = 0; i < 4; ++i) {  // 6 cases in 4 shards: sizes 2, 2, 1, 1
    StudyRunOptions o;
    o.database = dir / ("shard-" + std::to_string(i) + ".sqlite");
    o.shard_index = i;
    o.shard_count = 4;
    o.jobs = 2;
    EXPECT_EQ(run_study(study, o).ran, i < 2 ? 2u : 1u);
    shards.push_back(o.database);
  }
  EXPECT_EQ(merge_study_databases(shards, dir / "merged.sqlite"), 6);
  EXPECT_EQ(dump_results(dir / "merged.sqlite"), dump_results(whole.database));
  EXPECT_EQ(count_cases(dir / "merged.sqlite").with_rows, 6);
  EXPECT_EQ(count_cases(dir / "merged.sqlite").in_study, 6);
  // Shards left out: the merge is made (a look at partial results) and says it is short.
  const auto short_merge =
      test::run_wifislam("study merge " + shards[0].string() + " " + shards[2].string() + " -o " +
                             (dir / "short.sqlite").string(),
                         dir);
  EXPECT_EQ(short_merge.exit_code, 0) << short_merge.err;
  EXPECT_NE(short_merge.err.find("warning: 3 of the study's 6 cases have rows"), std::string::npos)
      << short_merge.err;
  const auto whole_merge = test::run_wifislam(
      "study merge " + shards[0].string() + " " + shards[1].string() + " " + shards[2].string() +
          " " + shards[3].string() + " -o " + (dir / "whole_merge.sqlite").string(),
      dir);
  EXPECT_EQ(whole_merge.exit_code, 0) << whole_merge.err;
  EXPECT_EQ(whole_merge.err.find("warning"), std::string::npos) << whole_merge.err;

  // A shard of another study file (one value more) is refused by merge and by run.
  const fs::path other_file =
      write_study(dir, "other", "  access_points.count: [10, 20, 30]\n  seed: [1, 2, 3]\n");
  const StudyFile other = load_study_file(other_file);
  StudyRunOptions o;
  o.database = dir / "other.sqlite";
  o.shard_count = 9;  // one case: quick
  run_study(other, o);
  shards.push_back(o.database);
  EXPECT_THROW(merge_study_databases(shards, dir / "merged2.sqlite"), InvalidInputError);
  EXPECT_FALSE(fs::exists(dir / "merged2.sqlite"));
  EXPECT_THROW(run_study(study, o), InvalidInputError);
  // Through the command line: exit 2, and a file that is no study database is never touched.
  test::write_file(dir / "notes.sqlite", "my notes");
  const auto r = test::run_wifislam(
      "study run " + file.string() + " -o " + (dir / "notes.sqlite").string() + " --force", dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(test::read_file(dir / "notes.sqlite"), "my notes");
  const auto foreign = test::run_wifislam(
      "study run " + file.string() + " -o " + (dir / "other.sqlite").string(), dir);
  EXPECT_EQ(foreign.exit_code, 2) << foreign.err;
  EXPECT_NE(foreign.err.find("--force"), std::string::npos) << foreign.err;
  fs::remove_all(dir);
}

// Issue 34: the same shard given twice merged to half a database without a word. One file twice
// (however spelt) and a copy of a shard already merged are refused, through the command line
// too (exit 2), and nothing is written.
// `study cases` lists the cases only once every one checks: a refused file prints no table (a
// script reading stdout must not take half a list for the study).
TEST(StudyRun, CasesListsTheTableOnlyWhenEveryCaseChecks) {
  const fs::path dir = test::scratch_folder();
  const fs::path good = write_study(dir, "good", "  access_points.count: [10, 20]\n");
  auto r = test::run_wifislam("study cases " + good.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 3) << r.out;  // header + 2 cases
  const fs::path bad = write_study(dir, "bad", "  access_points.count: [10, -5]\n");
  r = test::run_wifislam("study cases " + bad.string(), dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.out, "");
  // A vocabulary that is not there: named by `study cases` (it failed the first case of a run),
  // and a database that is not there by `study plot`: both missing inputs, exit 3.
  const fs::path vocabulary_file = dir / "vocabulary.yaml";
  test::write_file(vocabulary_file, "version: 1\nname: v\nscene: " + kScene +
                                        "\nlevel: slam\nslam: {frontend: orbslam}\naxes:\n"
                                        "  slam.vocabulary: [" +
                                        (dir / "none.bin").string() + "]\n");
  r = test::run_wifislam("study cases " + vocabulary_file.string(), dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("none.bin"), std::string::npos) << r.err;
  r = test::run_wifislam(
      "study plot " + (dir / "none.sqlite").string() + " -o " + (dir / "plots").string(), dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("none.sqlite: no such study database"), std::string::npos) << r.err;
  // A SLAM-level study's scratch folder for its cases goes beside the database: a file there is
  // named before any work (it was an internal error once a case started), and nothing is made.
  const fs::path slam_file = dir / "slam.yaml";
  test::write_file(slam_file, "version: 1\nname: slam\nscene: " + kScene +
                                  "\nlevel: slam\naxes:\n  seed: [1]\n");
  test::write_file(dir / "w.sqlite.work", "notes");
  r = test::run_wifislam("study run " + slam_file.string() + " -o " + (dir / "w.sqlite").string(),
                         dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("w.sqlite.work: a file where"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "w.sqlite"));
  // What goes into #SBATCH lines is checked: no line of sbatch's refusal, none added.
  for (const char* option : {"--time 'two hours'", "--partition 'a\n#SBATCH --mem=1'"}) {
    r = test::run_wifislam(
        "study slurm " + good.string() + " --tasks 1 -o " + (dir / "job").string() + " " + option,
        dir);
    EXPECT_EQ(r.exit_code, 2) << option << ": " << r.err;
    EXPECT_NE(r.err.find("expected a Slurm"), std::string::npos) << option << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir / "job")) << option;
  }
  fs::remove_all(dir);
}

TEST(StudyRun, TheSameShardTwiceIsRefused) {
  const fs::path dir = test::scratch_folder();
  const StudyFile study =
      load_study_file(write_study(dir, "twice", "  access_points.count: [10]\n  seed: [1, 2]\n"));
  std::vector<fs::path> shards;
  for (int i = 0; i < 2; ++i) {  // one case each
    StudyRunOptions o;
    o.database = dir / ("shard-" + std::to_string(i) + ".sqlite");
    o.shard_index = i;
    o.shard_count = 2;
    run_study(study, o);
    shards.push_back(o.database);
  }
  fs::copy_file(shards[0], dir / "copy.sqlite");
  const fs::path out = dir / "merged.sqlite";
  for (const auto& inputs : {std::vector<fs::path>{shards[0], shards[0]},
                             std::vector<fs::path>{shards[0], dir / "." / shards[0].filename()},
                             std::vector<fs::path>{shards[0], shards[1], dir / "copy.sqlite"}}) {
    try {
      merge_study_databases(inputs, out);
      ADD_FAILURE() << "merged " << inputs.back();
    } catch (const InvalidInputError& e) {
      EXPECT_NE(std::string(e.what()).find(inputs.back().string()), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(out));
  }
  const auto r = test::run_wifislam(
      "study merge " + shards[0].string() + " " + shards[0].string() + " -o " + out.string(), dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("given twice"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(merge_study_databases(shards, out), 2);
  fs::remove_all(dir);
}

// Co-linear access points (all on the south corridor's centre line) against scattered ones, on
// one scene and three seeds: far places (> 12 m) look alike to the Wi-Fi far more often when the
// APs lie on one line, and the route splits into fewer clusters.
// Issue 44: two `study run` on one database at once repeated each other's work and the second
// failed on a UNIQUE constraint; a damaged shard's merge said "database disk image is malformed"
// and named no file; a missing shard gave exit 2, not the I/O error's 3.
TEST(StudyRun, OneWriterADatabaseAndMergeNamesWhatIsWrongWithAShard) {
  const fs::path dir = test::scratch_folder();
  const fs::path file = write_study(dir, "locked", "  access_points.count: [10, 20]\n");
  const StudyFile study = load_study_file(file);
  {
    // A store open (a run in progress) holds the database: a second writer is refused at once.
    ResultStore first(dir / "db.sqlite", study, metric_columns(study), timing_columns(study.level));
    StudyRunOptions o;
    o.database = dir / "db.sqlite";
    try {
      run_study(study, o);
      ADD_FAILURE() << "a second writer was let in";
    } catch (const InvalidInputError& e) {
      EXPECT_NE(std::string(e.what()).find("another run is writing this database"),
                std::string::npos)
          << e.what();
    }
    const auto r = test::run_wifislam(
        "study run " + file.string() + " -o " + (dir / "db.sqlite").string(), dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    // --force with another study: refused as well, and the database being written is still
    // there (it was removed before the lock was looked at).
    const fs::path other = write_study(dir, "other", "  access_points.count: [5]\n");
    const auto forced = test::run_wifislam(
        "study run " + other.string() + " -o " + (dir / "db.sqlite").string() + " --force", dir);
    EXPECT_EQ(forced.exit_code, 2) << forced.err;
    EXPECT_NE(forced.err.find("another run is writing"), std::string::npos) << forced.err;
    EXPECT_EQ(ResultStore::read_identity(dir / "db.sqlite")->name, "locked");
    // A merge into it, or of it, while it is written: refused, nothing replaced.
    const auto into = test::run_wifislam(
        "study merge " + (dir / "db.sqlite").string() + " -o " + (dir / "m.sqlite").string(), dir);
    EXPECT_EQ(into.exit_code, 2) << into.err;
    EXPECT_NE(into.err.find("a run is writing it now"), std::string::npos) << into.err;
    EXPECT_FALSE(fs::exists(dir / "m.sqlite"));
  }
  StudyRunOptions o;
  o.database = dir / "db.sqlite";
  EXPECT_EQ(run_study(study, o).ran, 2u);  // free again once the first store is gone
  {
    // `study merge --force` onto a database a run is writing: refused, the run's file kept.
    const fs::path busy_file = write_study(dir, "busy", "  access_points.count: [5]\n");
    const StudyFile busy = load_study_file(busy_file);
    ResultStore writing(dir / "busy.sqlite", busy, metric_columns(busy),
                        timing_columns(busy.level));
    const auto r = test::run_wifislam("study merge " + (dir / "db.sqlite").string() + " -o " +
                                          (dir / "busy.sqlite").string() + " --force",
                                      dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("another run is writing"), std::string::npos) << r.err;
    EXPECT_EQ(ResultStore::read_identity(dir / "busy.sqlite")->name, "busy");
  }
  // --force with a case that does not check: refused before the database is touched.
  const fs::path bad = write_study(dir, "bad", "  access_points.count: [-5, 10]\n");
  const auto refused = test::run_wifislam(
      "study run " + bad.string() + " -o " + (dir / "db.sqlite").string() + " --force", dir);
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_EQ(rows_in(dir / "db.sqlite"), 2);

  // A damaged shard: named. A missing one: an I/O error.
  test::write_file(dir / "damaged.sqlite",
                   test::read_file(dir / "db.sqlite").substr(0, 4096) + std::string(8192, 'x'));
  auto r = test::run_wifislam("study merge " + (dir / "db.sqlite").string() + " " +
                                  (dir / "damaged.sqlite").string() + " -o " +
                                  (dir / "m.sqlite").string(),
                              dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("damaged.sqlite"), std::string::npos) << r.err;
  r = test::run_wifislam("study merge " + (dir / "db.sqlite").string() + " " +
                             (dir / "missing.sqlite").string() + " -o " +
                             (dir / "m.sqlite").string(),
                         dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("missing.sqlite"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "m.sqlite"));
  fs::remove_all(dir);
}

// A resumed run whose scene file was edited since its first rows: refused, not mixed (the rows
// of two versions of the scene in one table, each with its own scene_hash).
TEST(StudyRun, AResumeOnAnEditedSceneIsRefused) {
  const fs::path dir = test::scratch_folder();
  fs::copy_file(kScene, dir / "scene.yaml");
  const fs::path file = dir / "edited.yaml";
  test::write_file(file,
                   "version: 1\nname: edited\nscene: scene.yaml\nlevel: radio\naxes:\n"
                   "  seed: [1, 2]\n");
  StudyRunOptions first;
  first.database = dir / "db.sqlite";
  first.shard_count = 2;  // the first case only
  EXPECT_EQ(run_study(load_study_file(file), first).ran, 1u);
  // The same file again, unchanged: resumes.
  StudyRunOptions rest;
  rest.database = first.database;
  EXPECT_EQ(run_study(load_study_file(file), rest).ran, 1u);
  // Edited: every case's scene differs from the rows' own.
  std::string scene = test::read_file(dir / "scene.yaml");
  const std::string count = "count: 38";
  const std::size_t at = scene.find(count);
  ASSERT_NE(at, std::string::npos);
  scene.replace(at, count.size(), "count: 5");
  test::write_file(dir / "scene.yaml", scene);
  // (A new process, as a user's rerun is: this one keeps the scene it read.)
  const auto r = test::run_wifislam(
      "study run " + file.string() + " -o " + first.database.string() + " -q", dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("another version of its scene"), std::string::npos) << r.err;
  EXPECT_EQ(rows_in(first.database), 2);
  fs::remove_all(dir);
}

TEST(StudyRun, ScatteredAccessPointsTellPlacesApartBetterThanCoLinearOnes) {
  const fs::path dir = test::scratch_folder();
  const fs::path file = write_study(dir, "colinear",
                                    "  access_points.placement: [colinear, rooms, random]\n"
                                    "  access_points.count: [20]\n"
                                    "  access_points.line_to_m: [\"[20, 0]\"]\n"
                                    "  seed: [1, 2, 3]\n");
  const StudyFile study = load_study_file(file);
  double far[3] = {0, 0, 0}, clusters[3] = {0, 0, 0};
  for (const StudyCase& c : study.cases) {
    const ResultRow row = run_case(study, c, dir, 1).front();
    const int placement = c.values[0] == "colinear" ? 0 : c.values[0] == "rooms" ? 1 : 2;
    for (const ResultColumn& m : row.metrics) {
      if (m.name == "far_similar_share") far[placement] += std::get<double>(m.value) / 3;
      if (m.name == "clusters") clusters[placement] += std::get<std::int64_t>(m.value) / 3.0;
    }
  }
  for (int scattered : {1, 2}) {
    EXPECT_GT(far[0], 2.0 * far[scattered])
        << "co-linear " << far[0] << ", scattered " << far[scattered];
    EXPECT_LT(clusters[0], clusters[scattered]);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace wifislam::study
