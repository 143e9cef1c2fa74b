#pragma once
// Hand-made Wi-Fi scans for the Wi-Fi module's tests: one scan of given (BSSID, RSSI) readings,
// and two places whose signatures are far apart (A hears AP 0x10 loudest, B hears AP 0x30).

#include <cstdint>
#include <utility>
#include <vector>

#include "core/wifi_scan.hpp"

namespace wifislam::slam::test {

using ApReadings = std::vector<std::pair<std::uint64_t, int>>;  // (BSSID, RSSI dBm)

/// A one-second scan starting at `start_s` with `aps` on channel 1.
inline WifiScan scan_of(double start_s, const ApReadings& aps) {
  WifiScan scan;
  scan.start_time = Timestamp::from_seconds(start_s);
  scan.end_time = scan.time = Timestamp::from_seconds(start_s + 1.0);
  for (const auto& [ap, rssi] : aps) {
    scan.readings.push_back({MacAddress{ap}, 2412000, rssi, "corp"});
  }
  return scan;
}

inline const ApReadings kPlaceA = {{0x10, -40}, {0x20, -60}, {0x30, -90}};
inline const ApReadings kPlaceB = {{0x10, -90}, {0x20, -60}, {0x30, -40}};

}  // namespace wifislam::slam::test
