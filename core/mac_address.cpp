#include "core/mac_address.hpp"

#include <fmt/format.h>

namespace wifislam {

std::optional<MacAddress> MacAddress::parse(std::string_view text) {
  if (text.size() != 17) return std::nullopt;
  const char sep = text[2];
  if (sep != ':' && sep != '-') return std::nullopt;
  std::uint64_t value = 0;
  for (int byte = 0; byte < 6; ++byte) {
    const std::size_t at = byte * 3;
    if (byte > 0 && text[at - 1] != sep) return std::nullopt;
    for (int k = 0; k < 2; ++k) {
      const char c = text[at + k];
      int nibble;
      if (c >= '0' && c <= '9')
        nibble = c - '0';
      else if (c >= 'a' && c <= 'f')
        nibble = c - 'a' + 10;
      else if (c >= 'A' && c <= 'F')
        nibble = c - 'A' + 10;
      else
        return std::nullopt;
      value = (value << 4) | static_cast<std::uint64_t>(nibble);
    }
  }
  return MacAddress{value};
}

std::string MacAddress::to_string() const {
  return fmt::format("{:02x}:{:02x}:{:02x}:{:02x}:{:02x}:{:02x}", (value >> 40) & 0xFF,
                     (value >> 32) & 0xFF, (value >> 24) & 0xFF, (value >> 16) & 0xFF,
                     (value >> 8) & 0xFF, value & 0xFF);
}

}  // namespace wifislam
