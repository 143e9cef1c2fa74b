#include "core/option_table.hpp"

#include <charconv>
#include <limits>

#include "core/text_lines.hpp"

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

bool parse_number_list(std::string_view text, std::vector<double>& out, std::string& bad_entry) {
  std::vector<double> values;
  if (text != "none") {
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = text.find(',', start);
      std::string_view entry = text.substr(
          start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
      while (!entry.empty() && entry.front() == ' ') entry.remove_prefix(1);
      while (!entry.empty() && entry.back() == ' ') entry.remove_suffix(1);
      double value = 0;
      if (!parse_number(entry, value, Infinity::kRefused)) {
        bad_entry = std::string(entry);
        return false;
      }
      values.push_back(value);
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
  }
  out = std::move(values);
  return true;
}

std::string number_list_text(const std::vector<double>& values) {
  if (values.empty()) return "none";
  std::string out;
  for (double v : values) out += (out.empty() ? "" : ",") + format_double_exact(v);
  return out;
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
