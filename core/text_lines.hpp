#pragma once
// Reading line-oriented text files (TUM lists, CSV) with positions for error messages.

#include <cstddef>
#include <functional>
#include <istream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/input_file.hpp"

namespace wifislam {

struct TextLine {
  int number = 0;  // 1-based
  std::string text;
};

/// No line of our text formats comes near this; a longer one means the input is not a text file
/// of ours (a binary file, /dev/zero), and reading on would only fill memory.
inline constexpr std::size_t kMaxTextLineBytes = std::size_t{16} << 20;

/// Opens `path` for line reading (core/input_file.hpp: never blocks in open()): ParseError when
/// it is a folder, IoError when it cannot be opened. Pipes and devices are allowed (`<(...)` in a
/// shell); read_line caps what they give.
InputFile open_text_file(const std::string& path);

/// The next line of `in` without its "\n" or "\r\n"; false at the end. Throws ParseError at
/// `path`:`number` for a line longer than kMaxTextLineBytes, IoError on a read error.
bool read_line(std::istream& in, std::string& text, const std::string& path, int number);

/// Every line of a file in turn, read as a stream: memory holds one line whatever the file's
/// size, and a caller that throws at a bad line stops reading there. Throws as open_text_file and
/// read_line.
void for_each_text_line(const std::string& path, const std::function<void(const TextLine&)>& line);

/// All lines of a file; throws IoError naming the file when it cannot be read. For small files
/// (a survey, a system's list): for_each_text_line streams.
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
