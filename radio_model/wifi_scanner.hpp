#pragma once
// The receiver: one scan sweeps the channels of scan_channels() in order, dwelling
// `dwell_per_channel_s` on each, and reports every BSSID it heard with an integer RSSI.
//
// Per BSSID and scan: RSSI sample = mean RSSI (propagation_model.hpp) + fast fading
// N(0, fast_fading_sigma_db) - people, where with probability `people_probability` someone
// stands in the path of that AP during the scan and takes U(0, people_disturbance_db) dB.
// A sample below `sensitivity_dbm` is never heard; above it the beacon is decoded with
// probability 1 - exp(-(sample - sensitivity) / detection_width_db), so APs near the floor come
// and go between scans (as real cards report them). The fading spread is why the paper's robot
// stands still ~10 s: averaging a pause's scans beats one scan.
//
// Randomness is stateless: the draws of the scan starting at time t come from the sub-stream
// "wifi/scan/<t in ns>" of the seed, so a scan does not depend on which scans came before it.

#include <cstdint>
#include <functional>
#include <string>

#include <Eigen/Core>

#include "core/timestamp.hpp"
#include "core/wifi_scan.hpp"
#include "radio_model/propagation_model.hpp"
#include "sim/scene/scene.hpp"

namespace wifislam {

struct WifiScannerOptions {
  double sensitivity_dbm = -92.0;    // typical 802.11 receiver floor for beacons at 1 Mb/s
  double dwell_per_channel_s = 0.1;  // passive-scan dwell (one 102.4 ms beacon interval)
  double detection_width_db = 3.0;   // how far above the floor detection becomes near-certain
  std::string sensor_id = "wifi0";
  static WifiScannerOptions from_scene(const WifiScannerSpec& spec);
};

class WifiScanner {
 public:
  WifiScanner(const PropagationModel& model, WifiScannerOptions options, std::uint64_t seed);

  /// A scan starting at `start` with the receiver at `position_m` throughout.
  WifiScan scan(Timestamp start, const Eigen::Vector3d& position_m) const;
  /// A scan while moving: each channel is heard at the receiver position in the middle of its
  /// dwell.
  WifiScan scan(Timestamp start,
                const std::function<Eigen::Vector3d(Timestamp)>& position_at) const;

  /// Sweep time: dwell x number of channels.
  std::int64_t scan_duration_ns() const;
  const WifiScannerOptions& options() const { return options_; }

 private:
  const PropagationModel& model_;
  WifiScannerOptions options_;
  std::uint64_t seed_;
};

}  // namespace wifislam
