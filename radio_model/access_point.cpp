#include "radio_model/access_point.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace wifislam::radio_model {

const std::vector<std::string>& ssid_names() {
  static const std::vector<std::string> names = {"corp",  "corp-guest", "eduroam", "iot",
                                                 "voice", "lab",        "media",   "staff"};
  return names;
}

MacAddress MacAllocator::allocate(int ap_id) {
  Rng rng = Rng::stream(seed_, fmt::format("access_points/mac/{}", ap_id));
  for (;;) {
    std::uint64_t v = rng.next_u64() & 0xFFFFFFFFFFF0ULL;  // 48 bits, last nibble 0
    // Unicast (bit 0 of the first octet clear), locally administered (bit 1 set): never
    // mistaken for a real vendor's address.
    v = (v & ~(std::uint64_t{0x01} << 40)) | (std::uint64_t{0x02} << 40);
    if (used_.insert(v).second) return MacAddress{v};
  }
}

AccessPoint make_access_point(int id, const Eigen::Vector3d& position_m, double tx_power_dbm,
                              int ssids_per_radio, std::uint64_t seed, MacAllocator& macs) {
  if (ssids_per_radio < 1 || ssids_per_radio > kMaxSsidsPerRadio)
    throw InvalidInputError(
        fmt::format("access_points.ssids_per_radio must be between 1 and {} (got {})",
                    kMaxSsidsPerRadio, ssids_per_radio));
  AccessPoint ap;
  ap.id = id;
  ap.position_m = position_m;
  ap.tx_power_dbm = tx_power_dbm;
  const MacAddress base = macs.allocate(id);
  Rng rng = Rng::stream(seed, fmt::format("access_points/channels/{}", id));
  for (RadioBand band : {RadioBand::k2_4GHz, RadioBand::k5GHz}) {
    const auto channels = ap_channels(band);
    const int channel = channels[static_cast<std::size_t>(
        rng.uniform_int(0, static_cast<std::int64_t>(channels.size()) - 1))];
    const std::uint64_t nibble0 = band == RadioBand::k2_4GHz ? 0 : 8;
    for (int k = 0; k < ssids_per_radio; ++k) {
      Bssid b;
      b.mac = MacAddress{base.value | (nibble0 + static_cast<std::uint64_t>(k))};
      b.ssid = ssid_names()[static_cast<std::size_t>(k)];
      b.band = band;
      b.channel = channel;
      b.frequency_khz = channel_frequency_khz(band, channel);
      ap.bssids.push_back(std::move(b));
    }
  }
  return ap;
}

}  // namespace wifislam::radio_model
