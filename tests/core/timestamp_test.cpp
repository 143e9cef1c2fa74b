#include <gtest/gtest.h>

#include "core/timestamp.hpp"

namespace wifislam {
namespace {

TEST(Timestamp, ParsesDecimalSecondsExactlyToNanoseconds) {
  EXPECT_EQ(Timestamp::parse("1305031102.175304")->ns, 1305031102175304000LL);
  EXPECT_EQ(Timestamp::parse("0.000000001")->ns, 1);
  EXPECT_EQ(Timestamp::parse("12")->ns, 12'000'000'000LL);
  EXPECT_EQ(Timestamp::parse("-1.5")->ns, -1'500'000'000LL);
  EXPECT_EQ(Timestamp::parse(".5")->ns, 500'000'000LL);
}

TEST(Timestamp, RejectsWhatIsNotADecimalTime) {
  for (const char* bad : {"", ".", "1e9", "abc", "1.2.3", "1.0000000001", "12a", "+"}) {
    EXPECT_FALSE(Timestamp::parse(bad).has_value()) << bad;
  }
}

// What numpy.savetxt writes by default ("%.18e") and the TUM tools read with float(): an
// exponent, and more decimals than nanoseconds. Rounded to the nearest nanosecond; exact text
// stays exact.
TEST(Timestamp, ParseRoundedReadsWhatTheTumToolsRead) {
  EXPECT_EQ(Timestamp::parse_rounded("1.700000000000000000e+09")->ns, 1'700'000'000'000'000'000LL);
  EXPECT_EQ(Timestamp::parse_rounded("1.700000000033299923e+09")->ns, 1'700'000'000'033'299'923LL);
  EXPECT_EQ(Timestamp::parse_rounded("1.7000000000332999235e9")->ns, 1'700'000'000'033'299'924LL);
  EXPECT_EQ(Timestamp::parse_rounded("1305031102.175304")->ns, 1305031102175304000LL);
  EXPECT_EQ(Timestamp::parse_rounded("0.0000000014")->ns, 1);
  EXPECT_EQ(Timestamp::parse_rounded("0.0000000015")->ns, 2);
  EXPECT_EQ(Timestamp::parse_rounded("-1.5e-3")->ns, -1'500'000);
  EXPECT_EQ(Timestamp::parse_rounded("-0.0000000015")->ns, -2) << "half away from zero";
  EXPECT_EQ(Timestamp::parse_rounded("25E-1")->ns, 2'500'000'000LL);
  EXPECT_EQ(Timestamp::parse_rounded("1e-300")->ns, 0);
  EXPECT_EQ(Timestamp::parse_rounded("1e-50")->ns, 0);
  // Leading zeros and long digit strings are digits like any other; exponents far out give 0.
  EXPECT_EQ(Timestamp::parse_rounded(std::string(100, '0') + "1.5e0")->ns, 1'500'000'000LL);
  EXPECT_EQ(Timestamp::parse_rounded("0.00000000" + std::string(80, '9'))->ns, 10);
  EXPECT_EQ(Timestamp::parse_rounded("0e500")->ns, 0);
  EXPECT_EQ(Timestamp::parse_rounded("1.e5")->ns, 100'000'000'000'000LL);
  EXPECT_EQ(Timestamp::parse_rounded(".5e1")->ns, 5'000'000'000LL);
  EXPECT_EQ(Timestamp::parse_rounded("0.9999999995")->ns, 1'000'000'000LL) << "carries";
  // The last nanosecond a TUM file can hold does not round up past it.
  EXPECT_FALSE(Timestamp::parse_rounded("9223372035.9999999995").has_value());
  EXPECT_EQ(Timestamp::parse_rounded("9223372035.9999999985")->ns, 9'223'372'035'999'999'999LL);
  for (const char* bad : {"", ".", "e9", "1e", "1e+", "1.5e9.5", "nan", "inf", "1e10", "0x10",
                          "1..2", "1e9 ", "--1", "1e+-5", "1e-+5", "+", "-", ".e1"}) {
    EXPECT_FALSE(Timestamp::parse_rounded(bad).has_value()) << bad;
  }
}

// Issue 18 (found with the Wi-Fi times): ten digits of seconds overflowed 64-bit nanoseconds
// and wrapped to a time long ago.
TEST(Timestamp, TimesBeyondSixtyFourBitNanosecondsAreRefused) {
  EXPECT_EQ(Timestamp::parse("9223372035.999999999")->ns, 9'223'372'035'999'999'999LL);
  EXPECT_EQ(Timestamp::parse("-9223372035.5")->ns, -9'223'372'035'500'000'000LL);
  for (const char* far : {"9223372036", "9999999999.5", "-9999999999"}) {
    EXPECT_FALSE(Timestamp::parse(far).has_value()) << far;
  }
}

TEST(Timestamp, FormatsWithRequestedDecimalsAndRounds) {
  EXPECT_EQ(Timestamp::from_ns(1305031102175304000LL).to_string(6), "1305031102.175304");
  EXPECT_EQ(Timestamp::from_ns(33'333'333).to_string(6), "0.033333");
  EXPECT_EQ(Timestamp::from_ns(66'666'667).to_string(6), "0.066667");
  EXPECT_EQ(Timestamp::from_ns(-1'500'000'000LL).to_string(3), "-1.500");
  EXPECT_EQ(Timestamp::from_ns(7).to_string(9), "0.000000007");
  EXPECT_EQ(Timestamp::from_ns(2'000'000'000LL).to_string(0), "2");
}

TEST(Timestamp, MicrosecondTimesRoundTripThroughText) {
  for (std::int64_t us : {0LL, 1LL, 999'999LL, 33'333LL, 1'234'567'890'123LL}) {
    const Timestamp t = Timestamp::from_ns(us * 1000);
    EXPECT_EQ(Timestamp::parse(t.to_string(6)), t);
  }
}

// At Unix times a double holds seconds only to 2.4e-7 s: an offset such as --time-offset
// 1700000000.123456 is taken as the decimal it was written as, and differences are exact.
TEST(Timestamp, UnixTimesKeepNanosecondPrecision) {
  EXPECT_EQ(Timestamp::from_seconds_exact(1700000000.123456).ns, 1'700'000'000'123'456'000LL);
  EXPECT_EQ(Timestamp::from_seconds_exact(1700000000.333333).ns, 1'700'000'000'333'333'000LL);
  EXPECT_EQ(Timestamp::from_seconds(1700000000.333333).ns, 1'700'000'000'333'332'992LL);
  EXPECT_EQ(Timestamp::from_seconds_exact(-0.25).ns, -250'000'000LL);
  EXPECT_EQ(Timestamp::from_seconds_exact(1.0 / 3.0).ns, 333'333'333LL);  // > 9 decimals: rounded
  EXPECT_EQ(Timestamp::from_seconds_exact(0.0).ns, 0);
  const Timestamp a = Timestamp::from_ns(1'700'000'000'000'000'001LL);
  const Timestamp b = Timestamp::from_ns(1'700'000'000'000'000'000LL);
  EXPECT_EQ(a.seconds_since(b), 1e-9);
  EXPECT_EQ(a.seconds() - b.seconds(), 0.0);  // why seconds_since exists
  EXPECT_EQ(Timestamp::parse("1700000000.333333")->to_tum_string(), "1700000000.333333");
}

}  // namespace
}  // namespace wifislam
