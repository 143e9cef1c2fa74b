#include <gtest/gtest.h>

#include "core/mac_address.hpp"

namespace wifislam {
namespace {

TEST(MacAddress, ParsesAndFormatsCanonically) {
  const auto m = MacAddress::parse("00:1A:2b:3c:4D:5e");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->value, 0x001A2B3C4D5EULL);
  EXPECT_EQ(m->to_string(), "00:1a:2b:3c:4d:5e");
  EXPECT_EQ(MacAddress::parse("00-1a-2b-3c-4d-5e"), m);
}

TEST(MacAddress, RejectsUnknownFormats) {
  for (const char* bad : {"", "001a2b3c4d5e", "00:1a:2b:3c:4d", "00:1a:2b:3c:4d:5e:6f",
                          "00:1a-2b:3c:4d:5e", "0g:1a:2b:3c:4d:5e", "00:1a:2b:3c:4d:5"}) {
    EXPECT_FALSE(MacAddress::parse(bad).has_value()) << bad;
  }
}

TEST(MacAddress, LastNibbleIdentifiesTheBssidOfOneAccessPoint) {
  const auto a0 = *MacAddress::parse("aa:bb:cc:dd:ee:a0");
  const auto a3 = *MacAddress::parse("aa:bb:cc:dd:ee:a3");
  const auto b0 = *MacAddress::parse("aa:bb:cc:dd:ee:b0");
  EXPECT_EQ(a0.without_last_nibble(), a3.without_last_nibble());
  EXPECT_NE(a0.without_last_nibble(), b0.without_last_nibble());
}

}  // namespace
}  // namespace wifislam
