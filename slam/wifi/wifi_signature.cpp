#include "slam/wifi/wifi_signature.hpp"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "core/error.hpp"

namespace wifislam::slam::wifi {

WifiSignature::WifiSignature(std::vector<ApStrength> strengths) : strengths_(std::move(strengths)) {
  std::sort(strengths_.begin(), strengths_.end(),
            [](const ApStrength& a, const ApStrength& b) { return a.ap < b.ap; });
  for (std::size_t i = 1; i < strengths_.size(); ++i) {
    if (strengths_[i].ap == strengths_[i - 1].ap) {
      throw InvalidInputError("Wi-Fi signature lists access point " +
                              MacAddress{strengths_[i].ap}.to_string() + " twice");
    }
  }
}

std::string WifiSignature::to_text() const {
  std::string out;
  for (const ApStrength& s : strengths_) {
    if (!out.empty()) out += ';';
    out += fmt::format("{}={:.1f}", MacAddress{s.ap}.to_string(), s.rssi_dbm);
  }
  return out;
}

WifiSignature aggregate_scans(std::span<const WifiScan> scans) {
  struct Sum {
    double rssi_dbm = 0.0;
    int readings = 0;
  };
  std::map<AccessPointKey, Sum> sums;
  for (const WifiScan& scan : scans) {
    for (const WifiReading& reading : scan.readings) {
      Sum& sum = sums[access_point_key(reading.bssid)];
      sum.rssi_dbm += reading.rssi_dbm;
      ++sum.readings;
    }
  }
  std::vector<ApStrength> strengths;
  strengths.reserve(sums.size());
  for (const auto& [ap, sum] : sums) strengths.push_back({ap, sum.rssi_dbm / sum.readings});
  return WifiSignature(std::move(strengths));
}

}  // namespace wifislam::slam::wifi
