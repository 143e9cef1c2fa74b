#pragma once
// Wi-Fi signatures (paper, "Wi-Fi data processing"): the RSSI of every access point heard during
// one pause. An access point advertises several BSSIDs (bands, SSIDs) that differ only in the
// last nibble of the MAC; they are one AP, and its RSSI is the mean of all their readings.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/mac_address.hpp"
#include "core/wifi_scan.hpp"

namespace wifislam::slam::wifi {

/// One access point: the BSSID with its last nibble cleared.
using AccessPointKey = std::uint64_t;
inline AccessPointKey access_point_key(const MacAddress& bssid) {
  return bssid.without_last_nibble().value;
}

struct ApStrength {
  AccessPointKey ap = 0;
  double rssi_dbm = 0.0;
  friend bool operator==(const ApStrength&, const ApStrength&) = default;
};

class WifiSignature {
 public:
  WifiSignature() = default;
  /// `strengths` in any order; duplicate APs are not allowed (InvalidInputError).
  explicit WifiSignature(std::vector<ApStrength> strengths);

  /// Sorted by AP key, one entry per AP.
  const std::vector<ApStrength>& strengths() const { return strengths_; }
  bool empty() const { return strengths_.empty(); }
  std::size_t size() const { return strengths_.size(); }

  /// "ap=rssi;ap=rssi" with ap as a MAC (last nibble 0) and RSSI to 0.1 dB: the
  /// wifi_clusters.csv form.
  std::string to_text() const;

  friend bool operator==(const WifiSignature&, const WifiSignature&) = default;

 private:
  std::vector<ApStrength> strengths_;
};

/// The signature of the scans of one pause: every reading of every BSSID of an AP, over all the
/// scans, averaged with equal weight. (Averaging per scan first would weigh a scan that heard one
/// BSSID of the AP like one that heard four; the plain mean keeps every reading equal.)
WifiSignature aggregate_scans(std::span<const WifiScan> scans);

}  // namespace wifislam::slam::wifi
