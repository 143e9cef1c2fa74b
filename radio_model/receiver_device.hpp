#pragma once
// The receiver that scans: what makes one phone, laptop or module read the same air differently
// from another. Every scene has one (sensors.wifi.device; without it the reference receiver), and
// every dataset records it (calibration.yaml's wifi_scanner entry, manifest.json's parameters).
//
// What a device changes, per reading (wifi_scanner.hpp applies it to each sample before the
// sensitivity floor, so a device that reads lower also hears less):
//   reported = sample + rss_offset_db + (rss_gain - 1) (sample - kGainPivotDbm),
// then rounded to a multiple of quantisation_db and capped at the receiver's saturation.
// Devices are known to differ by such a linear map of RSS (Haeberlen et al., "Practical robust
// localization over large-scale 802.11 wireless networks", MobiCom 2004; Kjaergaard, "Indoor
// location fingerprinting with heterogeneous clients", Pervasive and Mobile Computing 7(1), 2011).
// The gain turns about kGainPivotDbm so that rss_offset_db alone is the difference in the middle
// of the usual indoor range; the map a + b x of those papers has b = rss_gain and
// a = rss_offset_db - (rss_gain - 1) kGainPivotDbm.
//
// Also the device's: its sensitivity floor, its passive-scan dwell, the bands it scans (a 2.4 GHz
// only module sweeps 11 channels, not 20) and how its operating system throttles scan requests.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "radio_model/radio_band.hpp"
#include "radio_model/radio_defaults.hpp"

namespace wifislam::radio_model {

/// The bands a device scans.
enum class DeviceBands { kBoth, k2_4GHzOnly, k5GHzOnly };

/// Limits an operating system puts on an app's scan requests (scan_throttle.hpp applies them).
enum class ScanThrottle {
  kNone,
  // Android 9 and later, for each foreground app: four scans in any two-minute period
  // (developer.android.com, "Wi-Fi scanning overview", section "Throttling").
  kAndroidForeground,
  // Android 9 and later, all background apps together: one scan in any 30-minute period (same
  // page).
  kAndroidBackground,
};

/// How many scan requests a throttle grants in any window of `window_s` seconds.
struct ThrottleLimit {
  int max_scans = 0;  // 0: no limit
  double window_s = 0.0;
};
ThrottleLimit throttle_limit(ScanThrottle throttle);

/// The pivot of the gain slope (see above).
inline constexpr double kGainPivotDbm = -70.0;

struct ReceiverDevice {
  std::string name = "reference";
  std::string source = {};  // where its numbers come from; written with it
  double rss_offset_db = 0.0;
  double rss_gain = 1.0;
  double sensitivity_dbm = defaults::kSensitivityDbm;
  int quantisation_db = 1;  // reported RSSI is a multiple of this (whole dBm: 1)
  double dwell_per_channel_s = defaults::kDwellPerChannelS;
  DeviceBands bands = DeviceBands::kBoth;
  ScanThrottle scan_throttle = ScanThrottle::kNone;

  bool scans(RadioBand band) const;
  /// A sample as this device reports it, before rounding (see above).
  double reported_dbm(double sample_dbm) const;
  /// A reported level rounded to the device's step, capped at `max_dbm`.
  int quantised_dbm(double reported_dbm, double max_dbm) const;
};

/// The devices the project ships, each with its source (receiver_device.cpp): "reference" first.
const std::vector<ReceiverDevice>& shipped_devices();
/// The shipped device of this name, if any.
std::optional<ReceiverDevice> shipped_device(std::string_view name);

std::string_view to_string(DeviceBands bands);
std::string_view to_string(ScanThrottle throttle);

}  // namespace wifislam::radio_model
