#include "core/option_table.hpp"

#include <charconv>
#include <limits>

namespace wifislam::options {

namespace {

template <typename T>
bool parse_whole(std::string_view text, T& out) {
  T value{};
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || text.empty()) return false;
  out = value;
  return true;
}

}  // namespace

bool parse_boolean(std::string_view text, bool& out) {
  if (text == "true" || text == "1" || text == "on") {
    out = true;
    return true;
  }
  if (text == "false" || text == "0" || text == "off") {
    out = false;
    return true;
  }
  return false;
}

bool parse_integer(std::string_view text, int& out) { return parse_whole(text, out); }

bool parse_int64(std::string_view text, std::int64_t& out) { return parse_whole(text, out); }

bool parse_uint64(std::string_view text, std::uint64_t& out) { return parse_whole(text, out); }

bool parse_number(std::string_view text, double& out, Infinity infinity) {
  if (infinity == Infinity::kAllowed && (text == "inf" || text == "infinity")) {
    out = std::numeric_limits<double>::infinity();
    return true;
  }
  double value = 0;
  if (!parse_whole(text, value) || !std::isfinite(value)) return false;
  out = value;
  return true;
}

std::pair<std::string, std::string> split_assignment(const std::string& source,
                                                     const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw ParseError(source, assignment, "expected key=value");
  }
  return {assignment.substr(0, eq), assignment.substr(eq + 1)};
}

}  // namespace wifislam::options
