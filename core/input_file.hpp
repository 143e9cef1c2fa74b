#pragma once
// Opening a file to read without ever blocking in open(): a named FIFO that no program writes
// would hold std::ifstream's open() for ever (a system file or a scene given as a FIFO hung the
// command). The file is opened non-blocking and switched back to blocking reads: a pipe that has a
// writer (`<(...)` in a shell) reads as it always did, and one that has none reads as empty, which
// the caller reports like any empty file. Folders are refused by name.

#include <cstdio>
#include <filesystem>
#include <istream>
#include <memory>
#include <string>
#include <string_view>

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

/// Whether an optional input file (a run folder's graph.json, a dataset's calibration.yaml) is
/// there: false when nothing is at `path` (or a link to nothing), true for a regular file or a
/// link to one. Anything else there (a folder, a device, a pipe) is the wrong kind of thing, bad
/// input rather than absent: ParseError naming `path` and `what` it should be.
bool input_file_present(const std::filesystem::path& path, std::string_view what);

/// A required input file: IoError naming `path` and `what` when nothing is there (I/O, exit 3);
/// ParseError when something else is (as input_file_present).
void require_input_file(const std::filesystem::path& path, std::string_view what);

}  // namespace wifislam
