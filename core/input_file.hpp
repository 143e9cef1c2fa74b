#pragma once
// Opening a file to read without ever blocking in open(): a named FIFO that no program writes
// would hold std::ifstream's open() for ever (a system file or a scene given as a FIFO hung the
// command). The file is opened non-blocking and switched back to blocking reads: a pipe that has a
// writer (`<(...)` in a shell) reads as it always did, and one that has none reads as empty, which
// the caller reports like any empty file. Folders are refused by name.

#include <cstdio>
#include <istream>
#include <memory>
#include <string>

namespace wifislam {

class InputFile {
 public:
  /// Throws ParseError when `path` is a folder, IoError naming it when it cannot be opened.
  explicit InputFile(const std::string& path);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  InputFile(InputFile&&) noexcept;
  InputFile& operator=(InputFile&&) noexcept;

  std::istream& stream() { return *stream_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::unique_ptr<std::streambuf> buffer_;
  std::unique_ptr<std::istream> stream_;
};

}  // namespace wifislam
