#pragma once
// Streaming, line-by-line reading of a text file with line numbers for error messages. Blank
// lines and '#' comments are skipped. Used by the dataset reader so that memory does not grow
// with the length of a dataset.

#include <string>

#include "core/text_lines.hpp"

namespace wifislam {

class LineCursor {
 public:
  /// Throws IoError naming the file when it cannot be opened.
  explicit LineCursor(std::string path);
  /// The next non-blank, non-comment line; false at the end of the file.
  bool next(TextLine& line);
  const std::string& path() const { return path_; }
  /// "path:line" for error messages.
  std::string where(int line_number) const { return path_ + ":" + std::to_string(line_number); }

 private:
  std::string path_;
  InputFile file_;
  int line_number_ = 0;
};

}  // namespace wifislam
