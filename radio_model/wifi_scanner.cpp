#include "radio_model/wifi_scanner.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "core/rng.hpp"

namespace wifislam {

WifiScannerOptions WifiScannerOptions::from_scene(const WifiScannerSpec& spec) {
  WifiScannerOptions o;
  o.sensitivity_dbm = spec.sensitivity_dbm;
  o.dwell_per_channel_s = spec.dwell_per_channel_s;
  return o;
}

WifiScanner::WifiScanner(const PropagationModel& model, WifiScannerOptions options,
                         std::uint64_t seed)
    : model_(model), options_(std::move(options)), seed_(seed) {}

std::int64_t WifiScanner::scan_duration_ns() const {
  const std::size_t channels =
      scan_channels(RadioBand::k2_4GHz).size() + scan_channels(RadioBand::k5GHz).size();
  return static_cast<std::int64_t>(std::llround(options_.dwell_per_channel_s * 1e9)) *
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
      static_cast<std::int64_t>(std::llround(options_.dwell_per_channel_s * 1e9));
  WifiScan out;
  out.sensor_id = options_.sensor_id;
  out.start_time = start;
  out.end_time = Timestamp::from_ns(start.ns + scan_duration_ns());
  out.time = out.end_time;

  std::int64_t slot = 0;
  for (RadioBand band : {RadioBand::k2_4GHz, RadioBand::k5GHz}) {
    for (int channel : scan_channels(band)) {
      const Timestamp mid = Timestamp::from_ns(start.ns + slot * dwell_ns + dwell_ns / 2);
      ++slot;
      std::optional<Eigen::Vector3d> where;
      for (std::size_t a = 0; a < aps.size(); ++a) {
        std::optional<RadioLink> link;
        for (const Bssid& b : aps[a].bssids) {
          if (b.band != band || b.channel != channel) continue;
          if (!where) where = position_at(mid);
          if (!link) link = model_.link(a, *where);
          // Always draw both numbers so one BSSID's outcome never shifts another's draws.
          const double fading = rng.normal() * prop.fast_fading_sigma_db;
          const double u = rng.uniform();
          const double sample = model_.mean_rssi_dbm(a, b, *link) + fading - people_db[a];
          const double margin = sample - options_.sensitivity_dbm;
          if (margin < 0.0) continue;
          if (u >= 1.0 - std::exp(-margin / options_.detection_width_db)) continue;
          // A receiver saturates: it never reports more than kMaxRssiDbm, however strong the
          // shadowing and fading draws are.
          out.readings.push_back(
              {b.mac, b.frequency_khz,
               static_cast<int>(std::lround(std::min<double>(sample, kMaxRssiDbm))), b.ssid});
        }
      }
    }
  }
  return out;
}

}  // namespace wifislam
