#pragma once
// Reading line-oriented text files (TUM lists, CSV) with positions for error messages.

#include <functional>
#include <span>
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

/// One data row of a CSV file: its fields, its 1-based line number, and "file:line" for errors.
struct CsvRow {
  const std::vector<std::string_view>& fields;
  int line = 0;
  const std::string& where;
};

/// Reads a comma-separated file whose first line (after blank and '#' lines, which are skipped
/// everywhere) must be exactly `columns`, and calls `row` for every data row. Throws ParseError
/// naming the file and line for a missing or wrong header or a row with another field count,
/// IoError when the file cannot be read.
void for_each_csv_row(const std::string& path, std::span<const char* const> columns,
                      const std::function<void(const CsvRow&)>& row);

/// Strict number parsing of a whole field; false when the field is not exactly one number.
bool parse_double(std::string_view field, double& out);
bool parse_int64(std::string_view field, long long& out);

/// Shortest decimal text that reads back to exactly `value` (std::to_chars).
std::string format_double_exact(double value);

}  // namespace wifislam
