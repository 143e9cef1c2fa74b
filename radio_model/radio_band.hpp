#pragma once
// Wi-Fi bands and channels: which band a radio works in and the centre frequency of a channel
// (IEEE 802.11-2020, 17.3.8.4.2 and 19.3.15.2: 2.4 GHz channel c at 2407 + 5c MHz for c = 1..13,
// 5 GHz channel c at 5000 + 5c MHz).

#include <cstdint>
#include <span>

namespace wifislam::radio_model {

enum class RadioBand { k2_4GHz, k5GHz };
const char* to_string(RadioBand band);

/// Centre frequency of channel `channel` in `band`, in MHz.
double channel_frequency_mhz(RadioBand band, int channel);
inline std::int64_t channel_frequency_khz(RadioBand band, int channel) {
  return static_cast<std::int64_t>(channel_frequency_mhz(band, channel) * 1000.0 + 0.5);
}

/// The channels access points are given (non-overlapping 2.4 GHz channels; 5 GHz UNII-1 and
/// UNII-3 channels, which need no radar detection and are the usual enterprise choice).
std::span<const int> ap_channels(RadioBand band);

/// The channels a scanner sweeps, in sweep order: 2.4 GHz channels 1-11 then the 5 GHz channels
/// above. 20 channels; at the default 0.1 s dwell a sweep takes 2 s, the scan interval.
std::span<const int> scan_channels(RadioBand band);

}  // namespace wifislam::radio_model
