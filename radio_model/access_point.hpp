#pragma once
// Access points as the simulation knows them: where they are, how loud, and the BSSIDs they
// advertise. Every AP has a 2.4 GHz and a 5 GHz radio; each radio advertises `ssids_per_radio`
// BSSIDs (one per SSID). All BSSIDs of an AP share the MAC address except its last nibble:
// 2.4 GHz BSSIDs end in 0..k-1, 5 GHz BSSIDs in 8..8+k-1 — the structure the paper's
// aggregation step undoes ("Wi-Fi data processing").

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/mac_address.hpp"
#include "core/rng.hpp"
#include "radio_model/radio_band.hpp"

namespace wifislam::radio_model {

struct Bssid {
  MacAddress mac;
  std::string ssid;
  RadioBand band = RadioBand::k2_4GHz;
  int channel = 1;
  std::int64_t frequency_khz = 0;
  double frequency_mhz() const { return static_cast<double>(frequency_khz) * 1e-3; }
};

struct AccessPoint {
  int id = 0;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  double tx_power_dbm = 20.0;  // EIRP of each radio
  std::vector<Bssid> bssids;   // 2.4 GHz ones first, then 5 GHz
  /// The MAC shared by all of this AP's BSSIDs (last nibble cleared).
  MacAddress base_mac() const {
    return bssids.empty() ? MacAddress{} : bssids.front().mac.without_last_nibble();
  }
};

/// An access point's transmit power (EIRP): a Wi-Fi radio's range. 36 dBm is the largest EIRP any
/// regulator allows in the 2.4 and 5 GHz bands. The scene schema and survey AP files check it.
inline constexpr double kMinTxPowerDbm = -10.0;
inline constexpr double kMaxTxPowerDbm = 36.0;

/// The most BSSIDs a radio can advertise (eight last-nibble values per radio).
inline constexpr int kMaxSsidsPerRadio = 8;

/// Hands out base MACs (last nibble 0) that never share their upper 44 bits: two access points
/// never collide, even after the paper's last-nibble aggregation. Deterministic from the seed.
class MacAllocator {
 public:
  explicit MacAllocator(std::uint64_t seed) : seed_(seed) {}
  /// The base MAC for access point `ap_id`: drawn from the sub-stream "access_points/mac/<id>"
  /// (so it does not depend on the other APs unless they collide), redrawn on collision.
  MacAddress allocate(int ap_id);
  /// Marks a base MAC as taken (an AP made by another allocator of the same seed).
  void reserve(MacAddress base) { used_.insert(base.value); }

 private:
  std::uint64_t seed_;
  std::set<std::uint64_t> used_;
};

/// Builds an access point with both radios and `ssids_per_radio` BSSIDs on each; channels are
/// drawn from ap_channels() with the sub-stream "access_points/channels/<id>". Throws
/// InvalidInputError if ssids_per_radio is outside [1, kMaxSsidsPerRadio].
AccessPoint make_access_point(int id, const Eigen::Vector3d& position_m, double tx_power_dbm,
                              int ssids_per_radio, std::uint64_t seed, MacAllocator& macs);

/// The SSID names used, in order (the same networks are offered on both bands).
const std::vector<std::string>& ssid_names();

}  // namespace wifislam::radio_model
