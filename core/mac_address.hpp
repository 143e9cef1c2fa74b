#pragma once
// 48-bit MAC addresses (BSSIDs). Text form "aa:bb:cc:dd:ee:ff" (lower-case on output;
// '-' separators and upper case accepted on input).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace wifislam {

struct MacAddress {
  std::uint64_t value = 0;  // low 48 bits

  static std::optional<MacAddress> parse(std::string_view text);
  std::string to_string() const;
  /// The address with its last nibble cleared: BSSIDs of one access point share it
  /// (paper, "Wi-Fi data processing").
  MacAddress without_last_nibble() const { return MacAddress{value & ~std::uint64_t{0xF}}; }

  friend constexpr auto operator<=>(const MacAddress&, const MacAddress&) = default;
};

}  // namespace wifislam
