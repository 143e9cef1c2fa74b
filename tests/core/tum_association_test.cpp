// The TUM associate.py convention: pairs closer than 0.02 s, greedily from the closest, each
// stamp used once, sorted by rgb time.
#include <gtest/gtest.h>

#include "core/tum_file_list.hpp"

namespace wifislam {
namespace {

std::vector<TumFileEntry> entries(const std::vector<std::string>& stamps, const std::string& dir) {
  std::vector<TumFileEntry> out;
  for (const auto& s : stamps) out.push_back({*Timestamp::parse(s), dir + "/" + s + ".png", 0});
  return out;
}

TEST(TumAssociation, PairsClosestStampsWithinTwentyMilliseconds) {
  // Stamps as in freiburg1_xyz: rgb and depth at ~30 Hz with small offsets.
  const auto rgb = entries({"1305031102.175304", "1305031102.211214", "1305031102.243211",
                            "1305031102.275326", "1305031102.311267"},
                           "rgb");
  const auto depth = entries({"1305031102.160407", "1305031102.194330", "1305031102.226738",
                              "1305031102.262886", "1305031102.295279", "1305031102.395279"},
                             "depth");
  const auto pairs = associate_tum(rgb, depth, 0.02);
  // associate.py's output for these stamps: the closest candidates go first, so .211214 takes
  // .226738 (0.0155 s) before .243211 can, and .243211 is left without a depth image.
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"1305031102.175304", "1305031102.160407"},
      {"1305031102.211214", "1305031102.226738"},
      {"1305031102.275326", "1305031102.262886"},
      {"1305031102.311267", "1305031102.295279"}};
  ASSERT_EQ(pairs.size(), expected.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    EXPECT_EQ(pairs[i].rgb_time.to_string(6), expected[i].first);
    EXPECT_EQ(pairs[i].depth_time.to_string(6), expected[i].second);
    EXPECT_LT(std::abs(pairs[i].rgb_time.seconds() - pairs[i].depth_time.seconds()), 0.02);
    EXPECT_EQ(pairs[i].depth_path, "depth/" + expected[i].second + ".png");
  }
}

TEST(TumAssociation, EachStampIsUsedOnceAndFarStampsStayAlone) {
  const auto rgb = entries({"1.000", "1.010", "2.000"}, "rgb");
  const auto depth = entries({"1.004", "1.500"}, "depth");
  const auto pairs = associate_tum(rgb, depth, 0.02);
  ASSERT_EQ(pairs.size(), 1u);  // 1.010 loses 1.004 to the closer 1.000; 2.000 has no partner
  EXPECT_EQ(pairs[0].rgb_time.to_string(3), "1.000");
  EXPECT_EQ(pairs[0].depth_time.to_string(3), "1.004");
  // Exactly 0.02 s apart is not a pair (associate.py uses a strict '<').
  EXPECT_TRUE(associate_tum(entries({"1.00"}, "rgb"), entries({"1.02"}, "depth"), 0.02).empty());
}

TEST(TumAssociation, AssociationLinesMatchAssociatePyOutput) {
  FramePair p{*Timestamp::parse("1.033333"), "rgb/1.033333.png", *Timestamp::parse("1.033333"),
              "depth/1.033333.png", 0};
  EXPECT_EQ(format_association_line(p), "1.033333 rgb/1.033333.png 1.033333 depth/1.033333.png\n");
}

}  // namespace
}  // namespace wifislam
