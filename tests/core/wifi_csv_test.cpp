#include "core/wifi_csv.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "tests/core/test_folder.hpp"

namespace wifislam {
namespace {

WifiScan make_scan(std::int64_t start_us, int n) {
  WifiScan scan;
  scan.start_time = Timestamp::from_ns(start_us * 1000);
  scan.end_time = Timestamp::from_ns((start_us + 3'500'000) * 1000);
  scan.time = scan.end_time;
  for (int i = 0; i < n; ++i) {
    scan.readings.push_back({*MacAddress::parse("02:1a:2b:3c:4d:5" + std::to_string(i)),
                             i % 2 ? 5180000 : 2412000, -40 - 3 * i, i % 2 ? "lab" : "campus"});
  }
  return scan;
}

TEST(WifiCsv, WrittenScansReadBackEqual) {
  const auto dir = test::fresh_folder("csv");
  std::vector<WifiScan> scans = {make_scan(0, 3), make_scan(2'000'000, 5),
                                 make_scan(10'000'000, 1)};
  std::string text = wifi_csv_header() + "\n";
  for (const auto& s : scans) text += format_wifi_csv_rows(s);
  test::write_text(dir / "wifi.csv", text);
  EXPECT_EQ(read_wifi_csv((dir / "wifi.csv").string()), scans);
  // LaMAR's column order.
  EXPECT_EQ(wifi_csv_header(),
            "timestamp,sensor_id,mac_addr,frequency_khz,rssi_dbm,name,scan_time_start_us,"
            "scan_time_end_us");
  EXPECT_EQ(format_wifi_csv_rows(make_scan(0, 1)),
            "3500000,wifi0,02:1a:2b:3c:4d:50,2412000,-40,campus,0,3500000\n");
}

std::string error_of(const std::string& text, const std::filesystem::path& file) {
  test::write_text(file, text);
  try {
    read_wifi_csv(file.string());
  } catch (const ParseError& e) {
    return e.what();
  }
  return "no error";
}

TEST(WifiCsv, MalformedRowsNameTheFileLineAndColumn) {
  const auto dir = test::fresh_folder("bad");
  const auto file = dir / "wifi.csv";
  const std::string header = wifi_csv_header() + "\n";
  const std::string good = "3500000,wifi0,02:1a:2b:3c:4d:50,2412000,-40,campus,0,3500000\n";
  std::string e = error_of(header + good + "3500000,wifi0,02:1a:2b:3c:4d:51,2412000\n", file);
  EXPECT_NE(e.find("wifi.csv:3"), std::string::npos) << e;
  EXPECT_NE(e.find("expected 8"), std::string::npos) << e;
  e = error_of(header + "3500000,wifi0,02:1a:2b:3c:4d,2412000,-40,campus,0,3500000\n", file);
  EXPECT_NE(e.find("wifi.csv:2"), std::string::npos) << e;
  EXPECT_NE(e.find("mac_addr"), std::string::npos) << e;
  EXPECT_NE(e.find("02:1a:2b:3c:4d"), std::string::npos) << e;
  e = error_of(header + "3500000,wifi0,02:1a:2b:3c:4d:50,2412000,loud,campus,0,3500000\n", file);
  EXPECT_NE(e.find("rssi_dbm"), std::string::npos) << e;
  e = error_of(header + good + "1000,wifi0,02:1a:2b:3c:4d:50,2412000,-40,campus,0,1000\n", file);
  EXPECT_NE(e.find("wifi.csv:3"), std::string::npos) << e;
  EXPECT_NE(e.find("earlier"), std::string::npos) << e;
  e = error_of("timestamp,sensor,mac\n" + good, file);
  EXPECT_NE(e.find("wifi.csv:1"), std::string::npos) << e;
}

// Issue 18: a timestamp of 2^63 / 1000 us or more wrapped when turned into nanoseconds and was
// read as a time long ago; +50 dBm passed as an RSSI.
TEST(WifiCsv, TimestampsThatWouldWrapAndRssiNoReceiverReportsAreRefused) {
  const auto dir = test::fresh_folder("range");
  const auto file = dir / "wifi.csv";
  const std::string header = wifi_csv_header() + "\n";
  const std::string good = "3500000,wifi0,02:1a:2b:3c:4d:50,2412000,-40,campus,0,3500000\n";
  std::string e = error_of(
      header + good +
          "9223372036854776,wifi0,02:1a:2b:3c:4d:50,2412000,-40,campus,0,9223372036854776\n",
      file);
  EXPECT_NE(e.find("wifi.csv:3"), std::string::npos) << e;
  EXPECT_NE(e.find("'timestamp'"), std::string::npos) << e;
  EXPECT_NE(e.find("year 2262"), std::string::npos) << e;
  e = error_of(header +
                   "3500000,wifi0,02:1a:2b:3c:4d:50,2412000,-40,campus,-9223372036854776,"
                   "3500000\n",
               file);
  EXPECT_NE(e.find("scan_time_start_us"), std::string::npos) << e;
  for (const char* rssi : {"50", "31", "-121", "-200"}) {
    e = error_of(
        header + good + "3500000,wifi0,02:1a:2b:3c:4d:51,2412000," + rssi + ",campus,0,3500000\n",
        file);
    EXPECT_NE(e.find("wifi.csv:3"), std::string::npos) << rssi << ": " << e;
    EXPECT_NE(e.find("'rssi_dbm'"), std::string::npos) << e;
    EXPECT_NE(e.find("-120 to 30 dBm"), std::string::npos) << e;
  }
  // The ends of the range are readings.
  test::write_text(file, header + "3500000,wifi0,02:1a:2b:3c:4d:50,2412000,30,campus,0,3500000\n" +
                             "3500000,wifi0,02:1a:2b:3c:4d:51,2412000,-120,campus,0,3500000\n" +
                             "9223372036854775,wifi0,02:1a:2b:3c:4d:51,2412000,-1,x,0,"
                             "9223372036854775\n");
  EXPECT_EQ(read_wifi_csv(file.string()).size(), 2u);
}

TEST(WifiCsv, RefusesToWriteWhatTheFormatCannotHold) {
  WifiScan scan = make_scan(0, 1);
  scan.readings[0].ssid = "guest,free";
  EXPECT_THROW(format_wifi_csv_rows(scan), InvalidInputError);
  scan = make_scan(0, 1);
  scan.time = Timestamp::from_ns(1500);
  EXPECT_THROW(format_wifi_csv_rows(scan), InvalidInputError);
}

}  // namespace
}  // namespace wifislam
