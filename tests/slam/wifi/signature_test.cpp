// Signatures: BSSIDs of one access point (same MAC but the last nibble) are one AP with the mean
// RSSI of all their readings; scans of one pause are grouped, a new pause starts after a gap or
// after the base moved.

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "slam/wifi/pause_signature_tracker.hpp"
#include "slam/wifi/wifi_signature.hpp"

namespace wifislam::slam {
namespace {

MacAddress mac(const char* text) { return *MacAddress::parse(text); }

WifiScan scan_at(double start_s, double end_s, std::vector<std::pair<const char*, int>> readings) {
  WifiScan scan;
  scan.start_time = Timestamp::from_seconds(start_s);
  scan.end_time = scan.time = Timestamp::from_seconds(end_s);
  for (const auto& [bssid, rssi] : readings)
    scan.readings.push_back({mac(bssid), 2412000, rssi, "corp"});
  return scan;
}

TEST(WifiSignature, BssidsDifferingInTheLastNibbleMergeIntoOneAccessPoint) {
  const std::vector<WifiScan> scans = {scan_at(0, 1,
                                               {{"02:00:00:00:00:a0", -50},
                                                {"02:00:00:00:00:a1", -60},
                                                {"02:00:00:00:00:a2", -70},
                                                {"02:00:00:00:00:a3", -80},
                                                {"02:00:00:00:00:b0", -40}})};
  const wifi::WifiSignature s = wifi::aggregate_scans(scans);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s.strengths()[0].ap, mac("02:00:00:00:00:a0").value);
  EXPECT_DOUBLE_EQ(s.strengths()[0].rssi_dbm, -65.0);  // (-50 - 60 - 70 - 80) / 4
  EXPECT_EQ(s.strengths()[1].ap, mac("02:00:00:00:00:b0").value);
  EXPECT_DOUBLE_EQ(s.strengths()[1].rssi_dbm, -40.0);
}

TEST(WifiSignature, AveragesEveryReadingOverTheScansOfAPause) {
  const std::vector<WifiScan> scans = {
      scan_at(0, 1, {{"02:00:00:00:00:a0", -50}, {"02:00:00:00:00:a1", -54}}),
      scan_at(2, 3, {{"02:00:00:00:00:a0", -56}}), scan_at(4, 5, {{"02:00:00:00:00:c4", -90}})};
  const wifi::WifiSignature s = wifi::aggregate_scans(scans);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_DOUBLE_EQ(s.strengths()[0].rssi_dbm, -160.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.strengths()[1].rssi_dbm, -90.0);
  EXPECT_EQ(s.to_text(), "02:00:00:00:00:a0=-53.3;02:00:00:00:00:c0=-90.0");
}

TEST(WifiSignature, RejectsADuplicateAccessPoint) {
  EXPECT_THROW(wifi::WifiSignature({{1, -50}, {1, -60}}), InvalidInputError);
}

TEST(PauseSignatureTracker, NoSignatureBeforeTheFirstScan) {
  wifi::PauseSignatureTracker tracker(wifi::WifiOptions{});
  EXPECT_EQ(tracker.current(), nullptr);
  tracker.observe_scan(scan_at(0, 1, {{"02:00:00:00:00:a0", -50}}));
  ASSERT_NE(tracker.current(), nullptr);
  EXPECT_EQ(tracker.pause_count(), 1);
}

TEST(PauseSignatureTracker, ATimeGapStartsANewPause) {
  wifi::PauseSignatureTracker tracker(wifi::WifiOptions{});  // pause_gap_s 3
  tracker.observe_scan(scan_at(0, 1, {{"02:00:00:00:00:a0", -50}}));
  tracker.observe_scan(scan_at(2, 3, {{"02:00:00:00:00:a0", -60}}));
  EXPECT_EQ(tracker.pause_count(), 1);
  EXPECT_DOUBLE_EQ(tracker.current()->strengths()[0].rssi_dbm, -55.0);
  tracker.observe_scan(scan_at(10, 11, {{"02:00:00:00:00:a0", -70}}));
  EXPECT_EQ(tracker.pause_count(), 2);
  EXPECT_DOUBLE_EQ(tracker.current()->strengths()[0].rssi_dbm, -70.0);
}

TEST(PauseSignatureTracker, OdometryMotionStartsANewPauseEvenWithoutAGap) {
  wifi::PauseSignatureTracker tracker(wifi::WifiOptions{});  // pause_motion_m 0.05
  OdometryReading odometry;
  tracker.observe_odometry(odometry);
  tracker.observe_scan(scan_at(0, 1, {{"02:00:00:00:00:a0", -50}}));
  odometry.base_in_odom.translation().x() = 0.01;  // wheel jitter: same pause
  tracker.observe_odometry(odometry);
  tracker.observe_scan(scan_at(1.5, 2.5, {{"02:00:00:00:00:a0", -52}}));
  EXPECT_EQ(tracker.pause_count(), 1);
  odometry.base_in_odom.translation().x() = 0.5;  // scanning while moving
  tracker.observe_odometry(odometry);
  tracker.observe_scan(scan_at(3, 4, {{"02:00:00:00:00:a0", -80}}));
  EXPECT_EQ(tracker.pause_count(), 2);
  EXPECT_DOUBLE_EQ(tracker.current()->strengths()[0].rssi_dbm, -80.0);
}

}  // namespace
}  // namespace wifislam::slam
