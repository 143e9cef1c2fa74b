#pragma once
// Time inside the program is integer nanoseconds (exact arithmetic, no drift when adding frame
// periods); files carry seconds as decimal text (TUM). Parsing goes straight from the decimal
// text to nanoseconds so no binary floating-point rounding creeps in.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace wifislam {

struct Timestamp {
  std::int64_t ns = 0;

  static Timestamp from_seconds(double seconds);
  /// The decimal number `seconds` was written as (its shortest round-trip text), exactly, when that
  /// has at most 9 decimals: 1700000000.123456 gives 1700000000123456000 ns, where from_seconds'
  /// product with 1e9 is off by up to a few hundred ns at Unix times. Otherwise as from_seconds.
  static Timestamp from_seconds_exact(double seconds);
  static constexpr Timestamp from_ns(std::int64_t n) { return Timestamp{n}; }
  /// Double seconds: only 2.4e-7 s apart at Unix times (~1.7e9 s), so time differences are taken
  /// in nanoseconds first (seconds_since) rather than between two seconds() values.
  double seconds() const { return static_cast<double>(ns) * 1e-9; }
  /// Seconds from `earlier` to this time, subtracted exactly in nanoseconds.
  double seconds_since(Timestamp earlier) const {
    return static_cast<double>(ns - earlier.ns) * 1e-9;
  }

  /// Decimal seconds with `decimals` digits after the point (TUM files use 6).
  /// Rounds to the nearest representable value (half away from zero).
  std::string to_string(int decimals = 6) const;

  /// As TUM files write times: 6 decimals (microseconds, as the TUM tools do), or 9 when the time
  /// has sub-microsecond digits, so that reading the text back gives exactly this time.
  std::string to_tum_string() const { return to_string(ns % 1000 == 0 ? 6 : 9); }

  /// Parses "1305031102.175304" style text (optional sign, up to 9 decimals) exactly.
  /// Returns nullopt for anything else (exponents, more than 9 decimals, garbage).
  static std::optional<Timestamp> parse(std::string_view text);

  /// Any decimal number of seconds a TUM tool reads (evaluate_ate.py's float()): parse()'s text
  /// exactly, and an exponent or more than 9 decimals ("1.700000000033299923e+09", numpy.savetxt's
  /// default) rounded to the nearest nanosecond, half away from zero. nullopt for garbage, nan,
  /// inf, or beyond parse()'s range.
  static std::optional<Timestamp> parse_rounded(std::string_view text);

  friend constexpr auto operator<=>(const Timestamp&, const Timestamp&) = default;
};

}  // namespace wifislam
