#include "radio_model/radio_band.hpp"

#include <array>

namespace wifislam::radio_model {

namespace {
constexpr std::array<int, 3> kAp24 = {1, 6, 11};
constexpr std::array<int, 9> kAp5 = {36, 40, 44, 48, 149, 153, 157, 161, 165};
constexpr std::array<int, 11> kScan24 = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
}  // namespace

const char* to_string(RadioBand band) {
  switch (band) {
    case RadioBand::k2_4GHz:
      return "2.4GHz";
    case RadioBand::k5GHz:
      return "5GHz";
  }
  return "unknown";
}

double channel_frequency_mhz(RadioBand band, int channel) {
  if (band == RadioBand::k2_4GHz) return channel == 14 ? 2484.0 : 2407.0 + 5.0 * channel;
  return 5000.0 + 5.0 * channel;
}

std::span<const int> ap_channels(RadioBand band) {
  if (band == RadioBand::k2_4GHz) return kAp24;
  return kAp5;
}

std::span<const int> scan_channels(RadioBand band) {
  if (band == RadioBand::k2_4GHz) return kScan24;
  return kAp5;
}

}  // namespace wifislam::radio_model
