#pragma once
// Wi-Fi scan records, as a receiver reports them: one scan = the BSSIDs heard during one sweep
// over the channels, each with an integer RSSI. Mirrors LaMAR's Wi-Fi record columns
// (core/dataset_format.hpp: timestamp, sensor_id, mac_addr, frequency_khz, rssi_dbm, name,
// scan_time_start_us, scan_time_end_us).

#include <cstdint>
#include <string>
#include <vector>

#include "core/mac_address.hpp"
#include "core/timestamp.hpp"

namespace wifislam {

/// The RSSI a reading may carry. -120 dBm lies below any receiver's noise floor (and is the
/// lowest sensitivity a scene may set); +30 dBm (1 W) is above the most any regulator lets an
/// access point radiate at 2.4 or 5 GHz (20-30 dBm EIRP), so no receiver ever reports more.
/// The reader refuses readings outside, and the simulated receiver saturates at the top.
inline constexpr int kMinRssiDbm = -120;
inline constexpr int kMaxRssiDbm = 30;

struct WifiReading {
  MacAddress bssid;
  std::int64_t frequency_khz = 0;
  int rssi_dbm = 0;
  std::string ssid;
  friend bool operator==(const WifiReading&, const WifiReading&) = default;
};

struct WifiScan {
  Timestamp time;        // when the scan result was reported (end of the sweep)
  Timestamp start_time;  // first channel dwell
  Timestamp end_time;    // last channel dwell
  std::string sensor_id = "wifi0";
  std::vector<WifiReading> readings;
  friend bool operator==(const WifiScan&, const WifiScan&) = default;
};

}  // namespace wifislam
