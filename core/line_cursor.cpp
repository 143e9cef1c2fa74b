#include "core/line_cursor.hpp"

#include "core/error.hpp"

namespace wifislam {

LineCursor::LineCursor(std::string path) : path_(std::move(path)), in_(path_, std::ios::binary) {
  if (!in_) throw IoError(path_ + ": cannot open file for reading");
}

bool LineCursor::next(TextLine& line) {
  std::string text;
  while (std::getline(in_, text)) {
    ++line_number_;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string::npos || text[first] == '#') continue;
    line.number = line_number_;
    line.text = std::move(text);
    return true;
  }
  if (in_.bad()) throw IoError(path_ + ": read error");
  return false;
}

}  // namespace wifislam
