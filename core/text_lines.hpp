#pragma once
// Reading line-oriented text files (TUM lists, CSV) with positions for error messages.

#include <string>
#include <string_view>
#include <vector>

namespace wifislam {

struct TextLine {
  int number = 0;  // 1-based
  std::string text;
};

/// All lines of a file; throws IoError naming the file when it cannot be read.
std::vector<TextLine> read_text_lines(const std::string& path);

/// Splits on runs of spaces/tabs (TUM) or, when `separator` is given, on that character (CSV).
std::vector<std::string_view> split_fields(std::string_view line, char separator = '\0');

/// Strict number parsing of a whole field; false when the field is not exactly one number.
bool parse_double(std::string_view field, double& out);
bool parse_int64(std::string_view field, long long& out);

/// Shortest decimal text that reads back to exactly `value` (std::to_chars).
std::string format_double_exact(double value);

}  // namespace wifislam
