#pragma once
// One CSV field as RFC 4180 writes it: as it is, or in double quotes (inner quotes doubled) when
// it holds a comma, a quote or a line break. Every CSV writer quotes through this.

#include <string>
#include <string_view>

namespace wifislam {

inline std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\n") == std::string_view::npos) return std::string(text);
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

}  // namespace wifislam
