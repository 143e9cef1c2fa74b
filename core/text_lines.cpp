#include "core/text_lines.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "core/error.hpp"

namespace wifislam {

InputFile open_text_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw ParseError(path, "", "is a folder; expected a text file");
  return InputFile(path);
}

bool read_line(std::istream& in, std::string& text, const std::string& path, int number) {
  // std::getline has no limit: on /dev/zero or a large binary file it grows one line until
  // memory runs out. Read in pieces and stop at the cap.
  text.clear();
  char piece[4096];
  bool any = false;
  while (true) {
    in.get(piece, sizeof piece, '\n');
    const std::streamsize n = in.gcount();
    any = any || n > 0;
    text.append(piece, static_cast<std::size_t>(n));
    if (text.size() > kMaxTextLineBytes)
      throw ParseError(path + ":" + std::to_string(number), "",
                       fmt::format("a line longer than {} MiB: not a text file of this tool's "
                                   "formats",
                                   kMaxTextLineBytes >> 20));
    if (in.bad()) throw IoError(path + ": read error");
    if (in.eof()) break;
    if (in.fail()) in.clear();  // get() extracted nothing: the next character is the newline
    if (in.peek() == '\n') {
      in.ignore();
      any = true;
      break;
    }
  }
  if (!any) return false;
  if (!text.empty() && text.back() == '\r') text.pop_back();
  return true;
}

void for_each_text_line(const std::string& path, const std::function<void(const TextLine&)>& line) {
  InputFile file = open_text_file(path);
  TextLine current;
  while (read_line(file.stream(), current.text, path, current.number + 1)) {
    ++current.number;
    line(current);
  }
}

std::vector<TextLine> read_text_lines(const std::string& path) {
  InputFile file = open_text_file(path);
  std::istream& in = file.stream();
  std::vector<TextLine> lines;
  std::string text;
  int number = 0;
  while (read_line(in, text, path, number + 1)) lines.push_back({++number, std::move(text)});
  return lines;
}

std::vector<std::string_view> split_fields(std::string_view line, char separator) {
  std::vector<std::string_view> fields;
  if (separator != '\0') {
    std::size_t start = 0;
    while (true) {
      const std::size_t end = line.find(separator, start);
      fields.push_back(line.substr(start, end == std::string_view::npos ? end : end - start));
      if (end == std::string_view::npos) break;
      start = end + 1;
    }
    return fields;
  }
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i >= line.size()) break;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
    fields.push_back(line.substr(i, j - i));
    i = j;
  }
  return fields;
}

bool parse_double(std::string_view field, double& out) {
  if (field.empty()) return false;
  if (field.front() == '+') field.remove_prefix(1);
  const auto [ptr, ec] = std::from_chars(field.data(), field.data() + field.size(), out);
  return ec == std::errc() && ptr == field.data() + field.size() && std::isfinite(out);
}

bool parse_int64(std::string_view field, long long& out) {
  if (field.empty()) return false;
  if (field.front() == '+') field.remove_prefix(1);
  const auto [ptr, ec] = std::from_chars(field.data(), field.data() + field.size(), out);
  return ec == std::errc() && ptr == field.data() + field.size();
}

std::string format_double_exact(double value) {
  char buf[64];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, ptr);
}

void for_each_csv_row(const std::string& path, std::span<const char* const> columns,
                      const std::function<void(const CsvRow&)>& row) {
  std::string header;
  for (const char* column : columns) header += (header.empty() ? "" : ",") + std::string(column);
  bool header_seen = false;
  for_each_text_line(path, [&](const TextLine& line) {
    if (line.text.empty() || line.text[0] == '#') return;
    const std::string where = path + ":" + std::to_string(line.number);
    const std::vector<std::string_view> fields = split_fields(line.text, ',');
    if (!header_seen) {
      header_seen = true;
      bool ok = fields.size() == columns.size();
      for (std::size_t i = 0; ok && i < fields.size(); ++i) ok = fields[i] == columns[i];
      if (!ok) throw ParseError(where, "header", "expected the header '" + header + "'");
      return;
    }
    if (fields.size() != columns.size()) {
      throw ParseError(where, "",
                       "expected " + std::to_string(columns.size()) +
                           " comma-separated fields, found " + std::to_string(fields.size()));
    }
    row(CsvRow{fields, line.number, where});
  });
  if (!header_seen) {
    throw ParseError(path + ":1", "header", "empty file: expected the CSV header '" + header + "'");
  }
}

}  // namespace wifislam
