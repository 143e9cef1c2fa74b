#include "radio_model/receiver_device.hpp"

#include <algorithm>
#include <cmath>

namespace wifislam::radio_model {

ThrottleLimit throttle_limit(ScanThrottle throttle) {
  switch (throttle) {
    case ScanThrottle::kAndroidForeground:
      return {4, 120.0};
    case ScanThrottle::kAndroidBackground:
      return {1, 1800.0};
    case ScanThrottle::kNone:
      break;
  }
  return {};
}

bool ReceiverDevice::scans(RadioBand band) const {
  switch (bands) {
    case DeviceBands::k2_4GHzOnly:
      return band == RadioBand::k2_4GHz;
    case DeviceBands::k5GHzOnly:
      return band == RadioBand::k5GHz;
    case DeviceBands::kBoth:
      break;
  }
  return true;
}

double ReceiverDevice::reported_dbm(double sample_dbm) const {
  // Written so that the reference device (offset 0, gain 1) returns the sample bit for bit.
  return sample_dbm + rss_offset_db + (rss_gain - 1.0) * (sample_dbm - kGainPivotDbm);
}

int ReceiverDevice::quantised_dbm(double reported, double max_dbm) const {
  const double capped = std::min(reported, max_dbm);
  if (quantisation_db == 1) return static_cast<int>(std::lround(capped));
  return static_cast<int>(std::lround(capped / quantisation_db)) * quantisation_db;
}

const std::vector<ReceiverDevice>& shipped_devices() {
  static const std::vector<ReceiverDevice> devices = [] {
    std::vector<ReceiverDevice> d;
    ReceiverDevice reference;
    reference.source =
        "the simulator's reference receiver: RSS as modelled, a typical 802.11 beacon floor";
    d.push_back(reference);

    ReceiverDevice foreground = reference;
    foreground.name = "android_foreground";
    foreground.source =
        "Android 9+ foreground app: four scans in any 2-minute period (developer.android.com, "
        "Wi-Fi scanning overview, Throttling); RSS as the reference receiver";
    foreground.scan_throttle = ScanThrottle::kAndroidForeground;
    d.push_back(foreground);

    ReceiverDevice background = reference;
    background.name = "android_background";
    background.source =
        "Android 9+ background apps: one scan in any 30-minute period (developer.android.com, "
        "Wi-Fi scanning overview, Throttling); RSS as the reference receiver";
    background.scan_throttle = ScanThrottle::kAndroidBackground;
    d.push_back(background);

    ReceiverDevice weaker = reference;
    weaker.name = "weaker_phone";
    weaker.source =
        "illustrative: reads 5 dB below the reference and hears 5 dB less (-87 dBm floor), the "
        "size of steady offsets measured between two phones on one survey; not a named model";
    weaker.rss_offset_db = -5.0;
    weaker.sensitivity_dbm = -87.0;
    d.push_back(weaker);

    ReceiverDevice esp32 = reference;
    esp32.name = "esp32";
    esp32.source =
        "Espressif ESP32 (datasheet: a 2.4 GHz Wi-Fi SoC): scans 2.4 GHz only; RSS, floor and "
        "dwell as the reference receiver";
    esp32.bands = DeviceBands::k2_4GHzOnly;
    d.push_back(esp32);
    return d;
  }();
  return devices;
}

std::optional<ReceiverDevice> shipped_device(std::string_view name) {
  for (const ReceiverDevice& d : shipped_devices())
    if (d.name == name) return d;
  return std::nullopt;
}

std::string_view to_string(DeviceBands bands) {
  switch (bands) {
    case DeviceBands::k2_4GHzOnly:
      return "2.4GHz";
    case DeviceBands::k5GHzOnly:
      return "5GHz";
    case DeviceBands::kBoth:
      break;
  }
  return "both";
}

std::string_view to_string(ScanThrottle throttle) {
  switch (throttle) {
    case ScanThrottle::kAndroidForeground:
      return "android_foreground";
    case ScanThrottle::kAndroidBackground:
      return "android_background";
    case ScanThrottle::kNone:
      break;
  }
  return "none";
}

}  // namespace wifislam::radio_model
