// The dataset bundle (fuzz/dataset_bundle.hpp) as scripts/fuzz.sh packs it: sections come back
// byte for byte (binary bytes, no final newline, empty files), the newline between sections is
// not part of a file, and names that could leave the scratch folder are skipped.
#include "fuzz/dataset_bundle.hpp"

#include <map>

#include <gtest/gtest.h>

namespace wifislam::fuzz {
namespace {

std::map<std::string, std::string> unpacked(std::string_view bundle) {
  std::map<std::string, std::string> files;
  for (const BundleFile& f : unpack_bundle(bundle)) files[f.name] = std::string(f.bytes);
  return files;
}

TEST(DatasetBundle, SectionsComeBackByteForByte) {
  const std::string png("\x89PNG\r\n\x1a\n\0\xff", 10);
  const std::string bundle = "=== empty.txt\n" + std::string() + "\n=== rgb.txt\n0 rgb/0.png\n" +
                             "\n=== rgb/0.png\n" + png + "\n=== wifi.csv\na,b\n\n\n" +
                             "\n=== last.txt\nno newline";
  const auto files = unpacked(bundle);
  ASSERT_EQ(files.size(), 5u);
  EXPECT_EQ(files.at("empty.txt"), "");
  EXPECT_EQ(files.at("rgb.txt"), "0 rgb/0.png\n");
  EXPECT_EQ(files.at("rgb/0.png"), png);
  EXPECT_EQ(files.at("wifi.csv"), "a,b\n\n\n");
  EXPECT_EQ(files.at("last.txt"), "no newline");
}

TEST(DatasetBundle, BytesBeforeTheFirstMarkerAndMarkersInsideALineAreData) {
  const auto files = unpacked("junk\n=== a.txt\nx === b.txt\n=== c.txt\n");
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files.at("a.txt"), "x === b.txt");
  EXPECT_EQ(files.at("c.txt"), "");
}

TEST(DatasetBundle, NamesThatCouldLeaveTheFolderAreSkipped) {
  const std::string bundle =
      "=== ../escape\nx\n=== /abs\nx\n=== a//b\nx\n=== a/b/c/d\nx\n=== ok/name.txt\ny\n"
      "=== ok/name.txt\nsecond\n=== sp ace\nx\n=== a/./b\nx";
  const std::vector<BundleFile> files = unpack_bundle(bundle);
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0].name, "ok/name.txt");
  EXPECT_EQ(files[0].bytes, "y");
}

}  // namespace
}  // namespace wifislam::fuzz
