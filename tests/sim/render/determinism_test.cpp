// Same pose and seed => byte-identical RGB and depth PNGs, within one process and across
// processes: the determinism every dataset promises.

#include <gtest/gtest.h>

#include <unistd.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/sim/render/render_frame_tool.hpp"
#include "tests/support/read_file.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::sim {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) { return test::scratch_folder(name); }

void expect_same_files(const fs::path& a_prefix, const fs::path& b_prefix) {
  for (const char* suffix : {"_rgb.png", "_depth.png"}) {
    const std::string a = test::read_file(a_prefix.string() + suffix);
    const std::string b = test::read_file(b_prefix.string() + suffix);
    EXPECT_GT(a.size(), 10000u) << suffix;
    EXPECT_TRUE(a == b) << suffix << " differs between " << a_prefix << " and " << b_prefix;
  }
}

TEST(RenderDeterminism, SamePoseAndSeedGiveIdenticalPngsInOneProcess) {
  const fs::path dir = fresh_dir("in_process");
  test::render_reference_frame((dir / "first").string(), 77, 3);
  test::render_reference_frame((dir / "second").string(), 77, 3);
  expect_same_files(dir / "first", dir / "second");
  // And the seed matters: other noise, other textures.
  test::render_reference_frame((dir / "other").string(), 78, 3);
  EXPECT_NE(test::read_file(dir / "first_rgb.png"), test::read_file(dir / "other_rgb.png"));
  EXPECT_NE(test::read_file(dir / "first_depth.png"), test::read_file(dir / "other_depth.png"));
  fs::remove_all(dir);
}

TEST(RenderDeterminism, SamePoseAndSeedGiveIdenticalPngsAcrossProcesses) {
  const fs::path dir = fresh_dir("processes");
  for (const char* name : {"a", "b"}) {
    const std::string command =
        std::string(WIFISLAM_RENDER_FRAME_TOOL) + " " + (dir / name).string() + " 77 3";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
  }
  expect_same_files(dir / "a", dir / "b");
  // The in-process render is the same frame as well.
  test::render_reference_frame((dir / "here").string(), 77, 3);
  expect_same_files(dir / "a", dir / "here");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace wifislam::sim
