// Paths recorded inside a folder under construction name where it will be once committed.
#include "core/final_paths.hpp"

#include <gtest/gtest.h>

namespace wifislam {
namespace {

namespace fs = std::filesystem;

TEST(FinalPaths, APathInTheStagingFolderNamesTheFinalOne) {
  const FinalPaths finals("/data/cmp.partial", "/data/cmp");
  EXPECT_EQ(finals.of("/data/cmp.partial/runs/a/wifi"), fs::path("/data/cmp/runs/a/wifi"));
  EXPECT_EQ(finals.of("/data/cmp.partial"), fs::path("/data/cmp"));
  EXPECT_EQ(finals.of("/data/cmp.partial/runs/../datasets/x"), fs::path("/data/cmp/datasets/x"));
  // Outside it, or only named alike: as given.
  EXPECT_EQ(finals.of("/data/other/run"), fs::path("/data/other/run"));
  EXPECT_EQ(finals.of("/data/cmp.partial2/run"), fs::path("/data/cmp.partial2/run"));
  // Relative paths are taken from the current folder, as the staging folder was.
  const FinalPaths relative("out.partial", "out");
  EXPECT_EQ(relative.of("out.partial/runs"), fs::absolute("out/runs").lexically_normal());
  // Nothing under construction: every path as given.
  EXPECT_EQ(FinalPaths().of("out.partial/runs"), fs::path("out.partial/runs"));
}

TEST(FinalPaths, EveryMentionInATextIsReplacedAndNoLongerName) {
  const FinalPaths finals("/data/cmp.partial", "/data/cmp");
  EXPECT_EQ(finals.in_text("exec sys /data/cmp.partial/datasets/x '/data/cmp.partial/runs/r'"),
            "exec sys /data/cmp/datasets/x '/data/cmp/runs/r'");
  EXPECT_EQ(finals.in_text("nothing written in /data/cmp.partial."),
            "nothing written in /data/cmp.");
  EXPECT_EQ(finals.in_text("/data/cmp.partial2/x and /data/cmp.partial_old"),
            "/data/cmp.partial2/x and /data/cmp.partial_old");
  EXPECT_EQ(finals.in_text("/data/cmp.partial.bak"), "/data/cmp.partial.bak");
  EXPECT_EQ(FinalPaths().in_text("/data/cmp.partial/x"), "/data/cmp.partial/x");
}

}  // namespace
}  // namespace wifislam
