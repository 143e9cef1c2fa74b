#include "core/utf8.hpp"

#include <cstdint>

namespace wifislam {

// Hand-rolled: a dozen lines against pulling in ICU or a converter for one yes/no question.
bool is_valid_utf8(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(text[k]); };
    const std::uint8_t b = byte(i);
    int length = 0;
    std::uint32_t code = 0, minimum = 0;
    if (b < 0x80) {
      ++i;
      continue;
    } else if ((b & 0xE0) == 0xC0) {
      length = 2, code = b & 0x1Fu, minimum = 0x80;
    } else if ((b & 0xF0) == 0xE0) {
      length = 3, code = b & 0x0Fu, minimum = 0x800;
    } else if ((b & 0xF8) == 0xF0) {
      length = 4, code = b & 0x07u, minimum = 0x10000;
    } else {
      return false;  // a continuation byte first, or 0xF8..0xFF
    }
    if (i + static_cast<std::size_t>(length) > text.size()) return false;
    for (int k = 1; k < length; ++k) {
      const std::uint8_t c = byte(i + static_cast<std::size_t>(k));
      if ((c & 0xC0) != 0x80) return false;
      code = (code << 6) | (c & 0x3Fu);
    }
    if (code < minimum || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return false;
    i += static_cast<std::size_t>(length);
  }
  return true;
}

}  // namespace wifislam
