// The receiver device (radio_model/receiver_device.hpp) on walls cast against with Embree: the
// same air, the same draws, read by different devices.
#include "radio_model/receiver_device.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "radio_model/propagation_model.hpp"
#include "radio_model/wifi_scanner.hpp"
#include "tests/radio_model/test_access_points.hpp"
#include "tests/radio_model/test_walls.hpp"

namespace wifislam::radio_model {
namespace {

using test::aps_along_x;

WallMesh brick_walls() {
  WallMesh mesh;
  for (int w = 0; w < 8; ++w)
    test::add_wall_x(mesh, 4.0f + 7.0f * w, 0.15f, 15.0f, 2.8f, WallMaterial::kBrick, w, 0.9f);
  return mesh;
}

using Readings = std::map<std::pair<std::uint64_t, std::int64_t>, int>;  // (BSSID, scan) -> RSSI

/// Every reading of scans along the walls, by BSSID and scan.
Readings survey(const PropagationModel& model, const ReceiverDevice& device) {
  WifiScannerOptions options;
  options.device = device;
  const WifiScanner scanner(model, options, 31);
  Readings out;
  for (int k = 0; k < 120; ++k) {
    const Timestamp t = Timestamp::from_seconds(2.0123457 * k);
    const Eigen::Vector3d p(0.5 * k, -1.0 + 0.02 * k, 1.0);
    for (const WifiReading& r : scanner.scan(t, p).readings) out[{r.bssid.value, k}] = r.rssi_dbm;
  }
  return out;
}

class ReceiverDeviceTest : public ::testing::Test {
 protected:
  ReceiverDeviceTest()
      : model_(brick_walls(), {-5, -15}, {70, 15}, aps_along_x(6, 5, 12.0), PropagationOptions{},
               5),
        reference_(survey(model_, ReceiverDevice{})) {}
  PropagationModel model_;
  Readings reference_;
};

TEST_F(ReceiverDeviceTest, AnOffsetShiftsEveryReadingAndItsFloorByTheSameAmount) {
  ASSERT_GT(reference_.size(), 1000u);
  ReceiverDevice lower;
  lower.rss_offset_db = -5.0;
  lower.sensitivity_dbm = ReceiverDevice{}.sensitivity_dbm - 5.0;  // hears what the reference does
  const Readings shifted = survey(model_, lower);
  ASSERT_EQ(shifted.size(), reference_.size());
  for (const auto& [key, rssi] : reference_) {
    ASSERT_TRUE(shifted.count(key));
    EXPECT_EQ(shifted.at(key), rssi - 5);
  }
}

TEST_F(ReceiverDeviceTest, ADeviceThatReadsLowerWithTheSameFloorHearsASubsetFiveDbLower) {
  const Readings weaker = survey(model_, *shipped_device("weaker_phone"));
  EXPECT_LT(weaker.size(), reference_.size() * 95 / 100);
  EXPECT_GT(weaker.size(), reference_.size() / 2);
  for (const auto& [key, rssi] : weaker) {
    ASSERT_TRUE(reference_.count(key)) << "the weaker phone heard what the reference did not";
    EXPECT_EQ(rssi, reference_.at(key) - 5);
    EXPECT_GE(rssi, -87);
  }
}

TEST_F(ReceiverDeviceTest, AGainStretchesReadingsAboutThePivot) {
  ReceiverDevice steep;
  steep.rss_gain = 1.2;
  steep.sensitivity_dbm = -200.0 / 1.2;  // far below: compare the readings both devices keep
  ReceiverDevice reference_far;
  reference_far.sensitivity_dbm = -200.0;
  const Readings a = survey(model_, reference_far), b = survey(model_, steep);
  std::size_t compared = 0;
  for (const auto& [key, rssi] : a) {
    if (!b.count(key)) continue;
    ++compared;
    // Both are rounded from one sample x: |b - (x + 0.2 (x + 70))| <= 0.5 with |x - a| <= 0.5.
    EXPECT_NEAR(b.at(key), rssi + 0.2 * (rssi - kGainPivotDbm), 0.5 + 0.5 * 1.2 + 1e-9);
  }
  EXPECT_GT(compared, 1000u);
}

TEST_F(ReceiverDeviceTest, QuantisedReadingsAreMultiplesOfTheStepWithinHalfAStep) {
  ReceiverDevice coarse;
  coarse.quantisation_db = 4;
  coarse.sensitivity_dbm = -200.0;
  ReceiverDevice fine;
  fine.sensitivity_dbm = -200.0;
  const Readings a = survey(model_, fine), b = survey(model_, coarse);
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [key, rssi] : b) {
    EXPECT_EQ(((rssi % 4) + 4) % 4, 0) << rssi;
    EXPECT_LE(std::abs(rssi - a.at(key)), 2.5);
  }
}

TEST_F(ReceiverDeviceTest, ADeviceOfOneBandSweepsOnlyItsChannelsAndHearsOnlyThatBand) {
  const ReceiverDevice esp32 = *shipped_device("esp32");
  WifiScannerOptions options;
  options.device = esp32;
  const WifiScanner scanner(model_, options, 31);
  EXPECT_EQ(scanner.scan_duration_ns(), 11 * 100'000'000);  // channels 1-11 at 0.1 s
  const Readings heard = survey(model_, esp32);
  ASSERT_FALSE(heard.empty());
  std::size_t reference_24 = 0;
  for (const auto& [key, rssi] : reference_) {
    (void)rssi;
    for (const AccessPoint& ap : model_.access_points())
      for (const Bssid& b : ap.bssids)
        if (b.mac.value == key.first && b.band == RadioBand::k2_4GHz) ++reference_24;
  }
  for (const auto& [key, rssi] : heard) {
    (void)rssi;
    bool is_24 = false;
    for (const AccessPoint& ap : model_.access_points())
      for (const Bssid& b : ap.bssids)
        if (b.mac.value == key.first) is_24 = b.band == RadioBand::k2_4GHz;
    EXPECT_TRUE(is_24);
  }
  // Same floor and air: about as many 2.4 GHz readings as the reference's.
  EXPECT_NEAR(static_cast<double>(heard.size()), static_cast<double>(reference_24),
              0.1 * reference_24);
}

TEST(ReceiverDevice, ShippedDevicesHaveSourcesAndTheReferenceIsTheIdentity) {
  ASSERT_FALSE(shipped_devices().empty());
  EXPECT_EQ(shipped_devices().front().name, "reference");
  for (const ReceiverDevice& d : shipped_devices()) EXPECT_FALSE(d.source.empty()) << d.name;
  const ReceiverDevice reference;
  for (double x : {-91.7, -70.0, -42.5, 3.0}) EXPECT_EQ(reference.reported_dbm(x), x);
  EXPECT_EQ(throttle_limit(ScanThrottle::kAndroidForeground).max_scans, 4);
  EXPECT_EQ(throttle_limit(ScanThrottle::kAndroidForeground).window_s, 120.0);
  EXPECT_EQ(throttle_limit(ScanThrottle::kNone).max_scans, 0);
  EXPECT_FALSE(shipped_device("no such phone"));
}

}  // namespace
}  // namespace wifislam::radio_model
