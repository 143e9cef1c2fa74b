#include "core/line_cursor.hpp"

#include "core/error.hpp"

namespace wifislam {

LineCursor::LineCursor(std::string path) : path_(std::move(path)), file_(open_text_file(path_)) {}

bool LineCursor::next(TextLine& line) {
  std::string text;
  while (read_line(file_.stream(), text, path_, line_number_ + 1)) {
    ++line_number_;
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string::npos || text[first] == '#') continue;
    line.number = line_number_;
    line.text = std::move(text);
    return true;
  }
  return false;
}

}  // namespace wifislam
