#include <gtest/gtest.h>

#include <set>

#include "core/error.hpp"
#include "radio_model/access_point.hpp"

namespace wifislam::radio_model {
namespace {

std::vector<AccessPoint> many_aps(std::uint64_t seed, int count, int ssids) {
  MacAllocator macs(seed);
  std::vector<AccessPoint> aps;
  for (int i = 0; i < count; ++i)
    aps.push_back(make_access_point(i, Eigen::Vector3d(i, 0, 2.5), 20.0, ssids, seed, macs));
  return aps;
}

TEST(AccessPoints, AllBssidsOfOneApDifferOnlyInTheLastNibble) {
  for (const AccessPoint& ap : many_aps(11, 300, 3)) {
    ASSERT_EQ(ap.bssids.size(), 6u);
    std::set<std::uint64_t> macs;
    for (const Bssid& b : ap.bssids) {
      EXPECT_EQ(b.mac.without_last_nibble(), ap.base_mac());
      EXPECT_TRUE(macs.insert(b.mac.value).second) << "duplicate BSSID within an AP";
      const std::uint64_t nibble = b.mac.value & 0xF;
      if (b.band == RadioBand::k2_4GHz)
        EXPECT_LT(nibble, 8u);
      else
        EXPECT_GE(nibble, 8u);
      EXPECT_EQ(b.frequency_khz, channel_frequency_khz(b.band, b.channel));
    }
    // Unicast, locally administered.
    EXPECT_EQ((ap.base_mac().value >> 40) & 0x3, 0x2u);
  }
}

TEST(AccessPoints, DifferentApsNeverCollideEvenAfterAggregation) {
  for (std::uint64_t seed : {1u, 2u, 99u}) {
    std::set<std::uint64_t> bases;
    for (const AccessPoint& ap : many_aps(seed, 2000, 8))
      EXPECT_TRUE(bases.insert(ap.base_mac().value).second) << "AP " << ap.id;
  }
}

TEST(AccessPoints, MacsAreDeterministicFromTheSeed) {
  const auto a = many_aps(5, 20, 3), b = many_aps(5, 20, 3), c = many_aps(6, 20, 3);
  int differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t k = 0; k < a[i].bssids.size(); ++k) {
      EXPECT_EQ(a[i].bssids[k].mac, b[i].bssids[k].mac);
      EXPECT_EQ(a[i].bssids[k].channel, b[i].bssids[k].channel);
    }
    differ += a[i].base_mac() != c[i].base_mac();
  }
  EXPECT_EQ(differ, 20);
}

TEST(AccessPoints, RejectsMoreSsidsThanALastNibbleCanHold) {
  MacAllocator macs(1);
  EXPECT_THROW(make_access_point(0, Eigen::Vector3d::Zero(), 20, 9, 1, macs), InvalidInputError);
  EXPECT_THROW(make_access_point(0, Eigen::Vector3d::Zero(), 20, 0, 1, macs), InvalidInputError);
}

}  // namespace
}  // namespace wifislam::radio_model
