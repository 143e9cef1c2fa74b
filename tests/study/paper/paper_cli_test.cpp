// `wifislam paper` as a user runs it, on one small part (ORB-SLAM on the A Hall twin: one case,
// one seed, 1 fps): it writes the report with every number of the paper, a second run redoes
// nothing, `wifislam study run` on the study file it wrote gives the same rows, and bad options
// and folders are refused before any work.

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "study/result_store.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"

namespace wifislam::study {
namespace {

namespace fs = std::filesystem;
using test::read_file;
using test::run_wifislam;

class PaperCli : public ::testing::Test {
 protected:
  void SetUp() override { scratch_ = test::scratch_folder(); }
  void TearDown() override { fs::remove_all(scratch_); }
  test::CliResult wifislam(const std::string& args) { return run_wifislam(args, scratch_); }
  fs::path scratch_;
};

int lines_of(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

/// The fields of one CSV row, a quoted field counting once whatever commas it holds.
int fields_of(const std::string& row) {
  int fields = 1;
  bool quoted = false;
  for (char c : row) {
    if (c == '"') quoted = !quoted;
    if (c == ',' && !quoted) ++fields;
  }
  return fields;
}

TEST_F(PaperCli, OneSmallPartWritesTheReportAndASecondRunRedoesNothing) {
  const fs::path dir = scratch_ / "paper";
  const std::string args =
      "paper -o " + dir.string() + " --parts orbslam --twins a_hall --fps 1 --jobs 2";
  auto r = wifislam(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path db = dir / "results" / "orbslam-a_hall-seed4004.sqlite";
  ASSERT_TRUE(fs::exists(db)) << r.err;
  const auto rows = dump_results(db);
  EXPECT_EQ(rows.size(), 2u);  // one case (min_matches 20), vanilla and Wi-Fi

  // Every number of the paper is in the table, judged; those of parts not run are n/a.
  const std::string csv = test::read_file(dir / "paper_vs_ours.csv");
  EXPECT_EQ(lines_of(csv), 1 + 239) << csv.substr(0, 400);
  EXPECT_NE(csv.find("table:rtabmap_rmse,a_hall,time_threshold_ms=70,vanilla,ate_rmse_m,0.4895 m"),
            std::string::npos);
  EXPECT_NE(csv.find("not applicable,not run"), std::string::npos);
  // Every row has the header's fields: a comma inside a field is quoted.
  std::istringstream csv_lines(csv);
  std::string row;
  std::getline(csv_lines, row);
  const int columns = fields_of(row);
  while (std::getline(csv_lines, row)) EXPECT_EQ(fields_of(row), columns) << row;
  EXPECT_NE(csv.find(",\"table:orbslam_overhead, caption\","), std::string::npos);
  const std::string report = test::read_file(dir / "report.md");
  EXPECT_NE(report.find("| [ORB-SLAM](orbslam.md) | 98 |"), std::string::npos) << report;
  EXPECT_NE(report.find("## Time per part"), std::string::npos) << report;
  const std::string orbslam = test::read_file(dir / "orbslam.md");
  EXPECT_NE(orbslam.find("## A Hall"), std::string::npos) << orbslam;
  EXPECT_NE(orbslam.find("We were not able to get any result for A Hall"), std::string::npos);
  for (const char* page : {"datasets.md", "rgbdslam.md", "rtabmap.md", "fabmap.md"})
    EXPECT_TRUE(fs::exists(dir / page)) << page;
  EXPECT_TRUE(fs::exists(dir / "studies" / "orbslam-a_hall-seed4004.yaml"));
  EXPECT_TRUE(fs::exists(dir / "datasets" / "a_hall-seed4004.json"));
  EXPECT_FALSE(fs::exists(dir / "work"));  // the scratch dataset is gone once its rows are in

  // A second run finds every case done: no run, the same rows.
  r = wifislam(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("0 runs and 0 localisations made, 1 cases already done"), std::string::npos)
      << r.err;
  EXPECT_EQ(dump_results(db), rows);

  // The study file it wrote, run by `study run`, gives the same rows.
  const fs::path alone = scratch_ / "alone.sqlite";
  r = wifislam("study run " + (dir / "studies" / "orbslam-a_hall-seed4004.yaml").string() + " -o " +
               alone.string() + " --jobs 2 -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(dump_results(alone), rows);
}

TEST_F(PaperCli, BadOptionsAndForeignFoldersAreRefusedBeforeAnyWork) {
  const fs::path dir = scratch_ / "p";
  for (const std::string& bad :
       {std::string("--parts bogus"), std::string("--parts rtabmap,"),
        std::string("--parts rtabmap,rtabmap"), std::string("--twins z_hall"),
        std::string("--seeds 0"), std::string("--fps nan"), std::string("--shard 2/2"),
        // --slurm's own options: checked, and refused without it (they were ignored, and the
        // whole reproduction started here).
        std::string("--slurm 2 --time 'two hours'"), std::string("--slurm 2 --partition 'a b'"),
        std::string("--partition gpu"), std::string("--time 02:00:00")}) {
    const auto r = wifislam("paper -o " + dir.string() + " " + bad);
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir)) << bad;
  }
  // A folder of the user's is not a paper folder: refused, untouched.
  test::write_file(scratch_ / "mine" / "notes.txt", "mine");
  auto r = wifislam("paper -o " + (scratch_ / "mine").string() + " --parts fabmap --twins c_hall");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("not a paper folder"), std::string::npos) << r.err;
  EXPECT_EQ(test::read_file(scratch_ / "mine" / "notes.txt"), "mine");
  EXPECT_EQ(std::distance(fs::directory_iterator(scratch_ / "mine"), fs::directory_iterator{}), 1);
  // --report-only on a folder that is not one.
  r = wifislam("paper -o " + (scratch_ / "none").string() + " --report-only");
  EXPECT_EQ(r.exit_code, 2) << r.err;
}

TEST_F(PaperCli, AFolderMadeAtOneFrameRateIsNotContinuedAtAnother) {
  const fs::path dir = scratch_ / "p";
  auto r = wifislam("paper -o " + dir.string() + " --parts fabmap --twins c_hall --fps 1 -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "localize" / "c_hall-seed1001" / "summary.json"));
  r = wifislam("paper -o " + dir.string() + " --parts fabmap --twins c_hall --fps 2 -q");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("made with --fps 1"), std::string::npos) << r.err;
  // --force starts over, in place: folders of the user's named like AtomicDirectory's staging and
  // set-aside folders beside it are neither a reason to refuse nor touched.
  test::write_file(scratch_ / "p.partial" / "notes.txt", "mine");
  test::write_file(scratch_ / "p.replaced" / "notes.txt", "mine too");
  r = wifislam("paper -o " + dir.string() + " --parts fabmap --twins c_hall --fps 2 -q --force");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "localize" / "c_hall-seed1001" / "summary.json"));
  EXPECT_EQ(test::read_file(scratch_ / "p.partial" / "notes.txt"), "mine");
  EXPECT_EQ(test::read_file(scratch_ / "p.replaced" / "notes.txt"), "mine too");
}

}  // namespace
}  // namespace wifislam::study
