#include "radio_model/wifi_scanner.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "core/rng.hpp"

namespace wifislam::radio_model {

WifiScanner::WifiScanner(const PropagationModel& model, WifiScannerOptions options,
                         std::uint64_t seed)
    : model_(model), options_(std::move(options)), seed_(seed) {
  const PropagationOptions& prop = model_.options();
  for (const AccessPoint& ap : model_.access_points()) {
    // One fading process per radio, at the carrier of its (shared) channel.
    std::vector<FadingProcess>& radios = fading_.emplace_back();
    for (RadioBand band : {RadioBand::k2_4GHz, RadioBand::k5GHz}) {
      const auto it = std::find_if(ap.bssids.begin(), ap.bssids.end(),
                                   [&](const Bssid& b) { return b.band == band; });
      const double frequency_mhz =
          it != ap.bssids.end() ? it->frequency_mhz() : (band == RadioBand::k5GHz ? 5500 : 2437);
      radios.emplace_back(
          prop.fast_fading_sigma_db, prop.fading_coherence_s, frequency_mhz,
          Rng::stream(
              seed_, fmt::format("wifi/fading/{}/{}", ap.base_mac().to_string(), to_string(band))));
    }
    std::vector<double>& offsets = beacon_offsets_s_.emplace_back();
    for (const Bssid& b : ap.bssids) {
      offsets.push_back(Rng::stream(seed_, fmt::format("wifi/beacon/{}", b.mac.to_string()))
                            .uniform(0.0, options_.beacon_interval_s));
    }
  }
}

bool WifiScanner::beacon_in_dwell(double offset_s, std::int64_t dwell_start_ns) const {
  const double interval_s = options_.beacon_interval_s;
  if (options_.device.dwell_per_channel_s >= interval_s) return true;
  // Time from the dwell's start to the BSSID's next beacon (target beacon transmission time).
  const double start_s = static_cast<double>(dwell_start_ns) * 1e-9;
  double wait_s = std::fmod(offset_s - start_s, interval_s);
  if (wait_s < 0.0) wait_s += interval_s;
  return wait_s < options_.device.dwell_per_channel_s;
}

std::int64_t WifiScanner::scan_duration_ns() const {
  std::size_t channels = 0;
  for (RadioBand band : {RadioBand::k2_4GHz, RadioBand::k5GHz})
    if (options_.device.scans(band)) channels += scan_channels(band).size();
  return static_cast<std::int64_t>(std::llround(options_.device.dwell_per_channel_s * 1e9)) *
         static_cast<std::int64_t>(channels);
}

WifiScan WifiScanner::scan(Timestamp start, const Eigen::Vector3d& position_m) const {
  return scan(start, [&](Timestamp) { return position_m; });
}

WifiScan WifiScanner::scan(Timestamp start,
                           const std::function<Eigen::Vector3d(Timestamp)>& position_at) const {
  const PropagationOptions& prop = model_.options();
  const auto& aps = model_.access_points();
  Rng rng = Rng::stream(seed_, fmt::format("wifi/scan/{}", start.ns));

  // People: one draw per AP per scan (a person near the robot or the AP blocks all its radios).
  std::vector<double> people_db(aps.size(), 0.0);
  for (std::size_t a = 0; a < aps.size(); ++a) {
    const bool blocked = rng.bernoulli(prop.people_probability);
    const double amount = rng.uniform(0.0, 1.0);
    if (prop.people_disturbance_db > 0.0 && blocked)
      people_db[a] = amount * prop.people_disturbance_db;
  }

  const std::int64_t dwell_ns =
      static_cast<std::int64_t>(std::llround(options_.device.dwell_per_channel_s * 1e9));
  WifiScan out;
  out.sensor_id = options_.sensor_id;
  out.start_time = start;
  out.end_time = Timestamp::from_ns(start.ns + scan_duration_ns());
  out.time = out.end_time;

  // Each AP's link at the last position it was asked for: a still receiver hears both radios
  // of an AP on different channels from the same spot, so one wall query serves both.
  struct LinkAt {
    Eigen::Vector3d position_m;
    RadioLink link;
  };
  std::vector<std::optional<LinkAt>> links(aps.size());

  std::int64_t slot = 0;
  const ReceiverDevice& device = options_.device;
  for (RadioBand band : {RadioBand::k2_4GHz, RadioBand::k5GHz}) {
    if (!device.scans(band)) continue;
    for (int channel : scan_channels(band)) {
      const std::int64_t dwell_start_ns = start.ns + slot * dwell_ns;
      const Timestamp mid = Timestamp::from_ns(dwell_start_ns + dwell_ns / 2);
      ++slot;
      std::optional<Eigen::Vector3d> where;
      for (std::size_t a = 0; a < aps.size(); ++a) {
        const RadioLink* link = nullptr;
        const FadingProcess& fading = fading_[a][band == RadioBand::k5GHz ? 1 : 0];
        std::optional<double> fading_db;
        for (std::size_t k = 0; k < aps[a].bssids.size(); ++k) {
          const Bssid& b = aps[a].bssids[k];
          if (b.band != band || b.channel != channel) continue;
          if (!where) where = position_at(mid);
          if (!link) {
            if (!links[a] || links[a]->position_m != *where)
              links[a] = LinkAt{*where, model_.link(a, *where)};
            link = &links[a]->link;
          }
          // Always draw both numbers so one BSSID's outcome never shifts another's draws.
          const double spread = rng.normal() * prop.bssid_spread_db;
          const double u = rng.uniform();
          if (!beacon_in_dwell(beacon_offsets_s_[a][k], dwell_start_ns)) continue;
          const double mean_dbm = model_.mean_rssi_dbm(a, b, *link);
          // Not heard whatever the fading: skip its 64 cosines. The bound is evaluated as the
          // level below with the fading replaced by a value at least as large, and rounding and
          // the device's map (gain > 0) are monotonic, so it is never below the level
          // (fading_process.hpp, max_abs_db).
          if (device.reported_dbm(mean_dbm + fading.max_abs_db() + spread - people_db[a]) -
                  device.sensitivity_dbm <
              0.0)
            continue;
          if (!fading_db) fading_db = fading.at_db(mid.seconds(), where->head<2>());
          const double reported =
              device.reported_dbm(mean_dbm + *fading_db + spread - people_db[a]);
          const double margin = reported - device.sensitivity_dbm;
          if (margin < 0.0) continue;
          if (u >= 1.0 - std::exp(-margin / options_.detection_width_db)) continue;
          // A receiver saturates: it never reports more than kMaxRssiDbm, however strong the
          // shadowing and fading draws are.
          out.readings.push_back(
              {b.mac, b.frequency_khz, device.quantised_dbm(reported, kMaxRssiDbm), b.ssid});
        }
      }
    }
  }
  return out;
}

}  // namespace wifislam::radio_model
