#pragma once
// The receiver: one scan sweeps the channels of scan_channels() that its device scans (both
// bands, or one: receiver_device.hpp), in order, dwelling the device's `dwell_per_channel_s` on
// each, and reports every BSSID it heard with an integer RSSI.
//
// Per BSSID and scan, heard on its channel at time t (the middle of the channel's dwell) and
// receiver position p:
//   RSSI sample = mean RSSI (propagation_model.hpp) + F_radio(t, p) + N(0, bssid_spread_db)
//                 - people,
// then as the device reads it: reported = device.reported_dbm(sample) (its offset and gain),
// F_radio the fading of the BSSID's radio (fading_process.hpp: shared by the radio's BSSIDs,
// correlated over `fading_coherence_s` at a still receiver, independent a few centimetres
// away), and with probability `people_probability` someone stands in the path of that AP during
// the scan and takes U(0, people_disturbance_db) dB. The fading is why the paper's robot stands
// still ~10 s: averaging a pause's scans beats one scan, though by less than for independent
// scans.
//
// Whether a BSSID is reported, in this order:
//  1. Beacon timing (passive scan): the BSSID beacons every `beacon_interval_s` (802.11's default
//     100 TU = 102.4 ms) from its own offset; a dwell that contains none of its beacons misses
//     it. With a 100 ms dwell that is 1 - 100 / 102.4 = 2.3 % of scans, whatever the signal.
//     Offsets are per BSSID (drivers stagger the beacons of an AP's virtual BSSs over the
//     interval), so one radio's BSSIDs are missed independently. Probe responses (active
//     scanning) are not modelled.
//  2. Sensitivity: a reported level below the device's `sensitivity_dbm` is never heard.
//  3. Decoding: above it, the beacon is decoded with probability
//     1 - exp(-(reported - sensitivity) / detection_width_db), so APs near the floor come and go
//     between scans (as real cards report them).
// The RSSI written is the reported level rounded to the device's quantisation step.
// A beacon must pass all three, so near the floor the miss rates multiply:
// P(heard) = P(beacon in dwell) x P(decoded | sample).
//
// Randomness is stateless: the per-scan draws of the scan starting at time t come from the
// sub-stream "wifi/scan/<t in ns>" of the seed; each radio's fading from "wifi/fading/<base MAC>/
// <band>" and each BSSID's beacon offset from "wifi/beacon/<MAC>". A scan does not depend on
// which scans came before it.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/timestamp.hpp"
#include "core/wifi_scan.hpp"
#include "radio_model/fading_process.hpp"
#include "radio_model/propagation_model.hpp"
#include "radio_model/radio_defaults.hpp"
#include "radio_model/receiver_device.hpp"

namespace wifislam::radio_model {

struct WifiScannerOptions {
  ReceiverDevice device;              // the reference receiver unless the scene names another
  double detection_width_db = 3.0;    // how far above the floor detection becomes near-certain
  double beacon_interval_s = 0.1024;  // 802.11 default: 100 TU of 1.024 ms
  std::string sensor_id = "wifi0";
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
  /// Whether the BSSID with beacon offset `offset_s` beacons during [start_s, start_s + dwell).
  bool beacon_in_dwell(double offset_s, std::int64_t dwell_start_ns) const;

  const PropagationModel& model_;
  WifiScannerOptions options_;
  std::uint64_t seed_;
  std::vector<std::vector<FadingProcess>> fading_;     // [AP][band]
  std::vector<std::vector<double>> beacon_offsets_s_;  // [AP][BSSID]
};

}  // namespace wifislam::radio_model
