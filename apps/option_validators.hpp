#pragma once
// Checks shared by the commands' options, where CLI11's own are not strict enough:
//   kSeedValidator      every `--seed`: a whole number in [0, 2^64 - 1], in plain digits. CLI11
//                       would otherwise turn "-1" or "18446744073709551616" into 2^64 - 1
//                       silently, while a scene file's `seed:` refuses both;
//   kPositiveFinite     rates and sizes such as `--fps`: CLI::PositiveNumber lets "nan" through;
//   finite_range(a, b)  every bounded real option: CLI::Range(a, b) lets "nan" through too (every
//                       comparison with nan is false), and a nan then reaches the model;
//   at_least(n)         counts (`--max-frames`, `--jobs`, `--seeds`): CLI::PositiveNumber's refusal
//                       reads "Value 0 not in range 0.000000 to 1797693134862315708...".
//   kSlurmTime,         `--time` and `--partition` of the Slurm jobs: written into #SBATCH lines,
//   kSlurmPartition     so text sbatch would refuse (or a newline adding a line) is refused here;
//   kNonEmptyPath       file outputs that may be left out (`--csv`, `--plan`, `--report`) or
//                       have a default: given as "", they were taken for not given.

#include <charconv>
#include <cmath>
#include <cstdint>
#include <memory>
#include <regex>
#include <string>
#include <utility>

#include <CLI/CLI.hpp>

namespace wifislam::cli {

inline const CLI::Validator kSeedValidator(
    [](std::string& text) -> std::string {
      std::uint64_t value = 0;
      const char* end = text.data() + text.size();
      const auto [ptr, ec] = std::from_chars(text.data(), end, value);
      if (text.empty() || text[0] == '-' || text[0] == '+' || ec != std::errc() || ptr != end) {
        return "a seed is a whole number from 0 to 18446744073709551615, got '" + text + "'";
      }
      return {};
    },
    "SEED");

/// A path that is given: an empty one would name no file (an optional output given as "" was
/// taken for not given and silently skipped, or became a file name such as "_rgb.png").
inline const CLI::Validator kNonEmptyPath(
    [](std::string& text) -> std::string {
      return text.empty() ? "the path is empty; give a file name" : std::string();
    },
    "PATH");

/// An input path that is given: an empty one was reported as ": not found" and the like, naming
/// no file (and `localize --vocabulary ''` used the shipped vocabulary).
inline const CLI::Validator kNonEmptyInput(
    [](std::string& text) -> std::string {
      return text.empty() ? "the path is empty; give the file or folder to read" : std::string();
    },
    "PATH");

/// A receiver device given: a shipped device's name or a device file; '' used the scene's own.
inline const CLI::Validator kNonEmptyDevice(
    [](std::string& text) -> std::string {
      return text.empty() ? "empty; give a shipped device's name or a device file" : std::string();
    },
    "DEVICE");

inline const CLI::Validator kPositiveFinite(
    [](std::string& text) -> std::string {
      double value = 0.0;
      const char* end = text.data() + text.size();
      const auto [ptr, ec] = std::from_chars(text.data(), end, value);
      if (ec != std::errc() || ptr != end || !std::isfinite(value) || !(value > 0.0)) {
        return "expected a positive finite number, got '" + text + "'";
      }
      return {};
    },
    "POSITIVE");

/// A real number in [lo, hi], NaN refused (CLI::Range's own test, value < lo || value > hi, is
/// false for NaN).
inline CLI::Validator finite_range(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        double value = 0.0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, value);
        if (ec != std::errc() || ptr != end || !(value >= lo && value <= hi)) {
          return "expected a number in [" + CLI::detail::to_string(lo) + ", " +
                 CLI::detail::to_string(hi) + "], got '" + text + "'";
        }
        return {};
      },
      "FLOAT in [" + CLI::detail::to_string(lo) + " - " + CLI::detail::to_string(hi) + "]");
}

/// A whole number of at least `lo`.
inline CLI::Validator at_least(std::int64_t lo) {
  return CLI::Validator(
      [lo](std::string& text) -> std::string {
        std::int64_t value = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, value);
        if (ec != std::errc() || ptr != end || value < lo) {
          return "expected a whole number of " + std::to_string(lo) + " or more, got '" + text +
                 "'";
        }
        return {};
      },
      lo == 1   ? "POSITIVE"
      : lo == 0 ? "NONNEGATIVE"
                : "AT LEAST " + std::to_string(lo));
}

/// A validator that accepts text `pattern` matches as a whole; other text gets "expected
/// <expected>, got '<text>'". The pattern is compiled once, when the validator is made.
inline CLI::Validator regex_validator(const std::string& pattern, std::string expected,
                                      std::string name,
                                      std::regex::flag_type flags = std::regex::ECMAScript) {
  auto format = std::make_shared<const std::regex>(pattern, flags);
  return CLI::Validator(
      [format, expected = std::move(expected)](std::string& text) -> std::string {
        if (std::regex_match(text, *format)) return {};
        return "expected " + expected + ", got '" + text + "'";
      },
      std::move(name));
}

/// Slurm's time formats (sbatch --time): minutes, minutes:seconds, hours:minutes:seconds,
/// days-hours, days-hours:minutes, days-hours:minutes:seconds, or -1, UNLIMITED, INFINITE (any
/// case).
inline const CLI::Validator kSlurmTime = regex_validator(
    R"(\d+(:\d{1,2}){0,2}|\d+-\d{1,2}(:\d{1,2}){0,2}|-1|unlimited|infinite)",
    "a Slurm time limit (minutes, [hours:]minutes:seconds or days-hours[:minutes[:seconds]], "
    "e.g. 02:00:00)",
    "TIME", std::regex::ECMAScript | std::regex::icase);

/// A Slurm partition name, or several separated by commas (letters, digits, '_', '-', '.').
inline const CLI::Validator kSlurmPartition = regex_validator(
    R"([A-Za-z0-9_.-]+(,[A-Za-z0-9_.-]+)*)",
    "a Slurm partition name (letters, digits, '_', '-', '.'; several separated by commas)",
    "PARTITION");

}  // namespace wifislam::cli
