#include "core/timestamp.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace wifislam {

Timestamp Timestamp::from_seconds(double seconds) {
  return Timestamp{static_cast<std::int64_t>(std::llround(seconds * 1e9))};
}

Timestamp Timestamp::from_seconds_exact(double seconds) {
  char text[64];
  // Shortest text that reads back as the same double; fixed notation so parse() can take it.
  const auto [end, ec] = std::to_chars(text, text + sizeof text, seconds, std::chars_format::fixed);
  if (ec == std::errc()) {
    if (const auto t = parse(std::string_view(text, static_cast<std::size_t>(end - text))))
      return *t;
  }
  return from_seconds(seconds);
}

std::string Timestamp::to_string(int decimals) const {
  if (decimals < 0) decimals = 0;
  if (decimals > 9) decimals = 9;
  std::int64_t unit = 1;
  for (int i = 0; i < 9 - decimals; ++i) unit *= 10;
  const bool negative = ns < 0;
  std::uint64_t mag = negative ? static_cast<std::uint64_t>(-(ns + 1)) + 1 : ns;
  std::uint64_t scaled = (mag + static_cast<std::uint64_t>(unit / 2)) / unit;  // round half up
  std::uint64_t scale = 1;
  for (int i = 0; i < decimals; ++i) scale *= 10;
  std::string out = negative && scaled != 0 ? "-" : "";
  out += std::to_string(scaled / scale);
  if (decimals > 0) {
    std::string frac = std::to_string(scaled % scale);
    out += "." + std::string(decimals - frac.size(), '0') + frac;
  }
  return out;
}

std::optional<Timestamp> Timestamp::parse(std::string_view text) {
  if (text.empty()) return std::nullopt;
  bool negative = false;
  std::size_t i = 0;
  if (text[0] == '-' || text[0] == '+') {
    negative = text[0] == '-';
    i = 1;
  }
  std::int64_t whole = 0;
  std::size_t whole_digits = 0;
  for (; i < text.size() && text[i] != '.'; ++i) {
    if (text[i] < '0' || text[i] > '9' || whole_digits >= 10) return std::nullopt;
    whole = whole * 10 + (text[i] - '0');
    ++whole_digits;
  }
  std::int64_t frac_ns = 0;
  std::size_t frac_digits = 0;
  if (i < text.size()) {
    ++i;  // the '.'
    for (; i < text.size(); ++i) {
      if (text[i] < '0' || text[i] > '9' || frac_digits >= 9) return std::nullopt;
      frac_ns = frac_ns * 10 + (text[i] - '0');
      ++frac_digits;
    }
  }
  if (whole_digits == 0 && frac_digits == 0) return std::nullopt;
  // Ten digits of seconds reach 9999999999 s, beyond the 64-bit nanoseconds (the year 2262):
  // refused rather than wrapped.
  constexpr std::int64_t kMaxWholeS =
      (std::numeric_limits<std::int64_t>::max() - 999'999'999) / 1'000'000'000;
  if (whole > kMaxWholeS) return std::nullopt;
  for (std::size_t k = frac_digits; k < 9; ++k) frac_ns *= 10;
  std::int64_t total = whole * 1'000'000'000 + frac_ns;
  return Timestamp{negative ? -total : total};
}

std::optional<Timestamp> Timestamp::parse_rounded(std::string_view text) {
  if (const std::optional<Timestamp> exact = parse(text)) return exact;
  // The number as its digits and where the decimal point falls among them, exponent applied;
  // then parse() reads the first 9 decimals exactly and the 10th rounds.
  std::size_t i = 0;
  bool negative = false;
  if (!text.empty() && (text[0] == '-' || text[0] == '+')) {
    negative = text[0] == '-';
    i = 1;
  }
  std::string digits;
  std::int64_t point = -1;
  for (; i < text.size() && text[i] != 'e' && text[i] != 'E'; ++i) {
    if (text[i] == '.') {
      if (point >= 0) return std::nullopt;
      point = static_cast<std::int64_t>(digits.size());
    } else if (text[i] >= '0' && text[i] <= '9') {
      if (digits.size() >= 64) return std::nullopt;
      digits += text[i];
    } else {
      return std::nullopt;
    }
  }
  if (digits.empty()) return std::nullopt;
  if (point < 0) point = static_cast<std::int64_t>(digits.size());
  if (i < text.size()) {
    int exponent = 0;
    const char* first = text.data() + i + 1;
    const char* last = text.data() + text.size();
    if (first < last && *first == '+') ++first;  // from_chars takes '-' only
    const auto [end, ec] = std::from_chars(first, last, exponent);
    if (ec != std::errc() || end != last || first == last) return std::nullopt;
    if (exponent > 100 || exponent < -100) return std::nullopt;  // far beyond the range anyway
    point += exponent;
  }
  const std::int64_t n = static_cast<std::int64_t>(digits.size());
  if (point < 0) digits.insert(0, static_cast<std::size_t>(-point), '0'), point = 0;
  if (point > n) digits.append(static_cast<std::size_t>(point - n), '0');
  std::string whole = digits.substr(0, static_cast<std::size_t>(point));
  std::string fraction = digits.substr(static_cast<std::size_t>(point));
  whole.erase(0, std::min(whole.find_first_not_of('0'), whole.size()));
  if (whole.empty()) whole = "0";
  const bool round_up = fraction.size() > 9 && fraction[9] >= '5';
  fraction.resize(std::min<std::size_t>(fraction.size(), 9));
  std::optional<Timestamp> t = parse(whole + (fraction.empty() ? "" : "." + fraction));
  if (!t) return std::nullopt;
  if (round_up) {
    if (t->ns == std::numeric_limits<std::int64_t>::max()) return std::nullopt;
    t->ns += 1;
  }
  if (negative) t->ns = -t->ns;
  return t;
}

}  // namespace wifislam
