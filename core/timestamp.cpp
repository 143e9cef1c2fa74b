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
  // The number as its significant digits and where the decimal point falls among them, exponent
  // applied; then parse() reads the first 9 decimals exactly and the 10th rounds.
  std::size_t i = 0;
  bool negative = false;
  if (!text.empty() && (text[0] == '-' || text[0] == '+')) {
    negative = text[0] == '-';
    i = 1;
  }
  // Beyond 40 significant digits nothing reaches a nanosecond: parse() takes 10 digits of
  // seconds and 9 decimals. Digits past the cap still move the point when they are whole seconds.
  constexpr std::size_t kMaxSignificantDigits = 40;
  std::string digits;
  std::int64_t point = 0;  // digits before the decimal point (negative: zeros after it)
  bool seen_point = false, any_digit = false;
  for (; i < text.size() && text[i] != 'e' && text[i] != 'E'; ++i) {
    const char c = text[i];
    if (c == '.') {
      if (seen_point) return std::nullopt;
      seen_point = true;
    } else if (c >= '0' && c <= '9') {
      any_digit = true;
      if (digits.empty() && c == '0') {
        if (seen_point) --point;  // a leading zero after the point
      } else if (digits.size() < kMaxSignificantDigits) {
        digits += c;
        if (!seen_point) ++point;
      } else if (!seen_point) {
        ++point;
      }
    } else {
      return std::nullopt;
    }
  }
  if (!any_digit) return std::nullopt;
  if (i < text.size()) {
    ++i;  // the 'e'
    bool exponent_negative = false;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) exponent_negative = text[i++] == '-';
    if (i == text.size()) return std::nullopt;
    std::int64_t exponent = 0;
    for (; i < text.size(); ++i) {
      if (text[i] < '0' || text[i] > '9') return std::nullopt;
      exponent = std::min<std::int64_t>(exponent * 10 + (text[i] - '0'), 1'000'000);
    }
    point += exponent_negative ? -exponent : exponent;
  }
  if (digits.empty() || point <= -10) return Timestamp{0};  // zero, or below half a nanosecond
  if (point > 10) return std::nullopt;                      // parse()'s ten digits of seconds
  const std::int64_t n = static_cast<std::int64_t>(digits.size());
  std::string whole, fraction;
  if (point <= 0) {
    fraction = std::string(static_cast<std::size_t>(-point), '0') + digits;
  } else {
    whole = digits.substr(0, static_cast<std::size_t>(std::min(point, n)));
    if (point > n) whole.append(static_cast<std::size_t>(point - n), '0');
    if (point < n) fraction = digits.substr(static_cast<std::size_t>(point));
  }
  if (whole.empty()) whole = "0";
  const bool round_up = fraction.size() > 9 && fraction[9] >= '5';
  fraction.resize(std::min<std::size_t>(fraction.size(), 9));
  std::optional<Timestamp> t = parse(whole + (fraction.empty() ? "" : "." + fraction));
  if (!t) return std::nullopt;
  if (round_up) {
    // The last nanosecond parse() reads: rounding beyond it would give a time no TUM file of
    // ours can hold (its text would not read back).
    if (t->ns ==
        (std::numeric_limits<std::int64_t>::max() - 999'999'999) / 1'000'000'000 * 1'000'000'000 +
            999'999'999)
      return std::nullopt;
    t->ns += 1;
  }
  if (negative) t->ns = -t->ns;
  return t;
}

}  // namespace wifislam
