#include "core/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <ext/stdio_filebuf.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "core/error.hpp"

namespace wifislam {

InputFile::InputFile(const std::string& path) : path_(path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    if (errno == EISDIR) throw ParseError(path, "", "is a folder; expected a file");
    throw IoError(fmt::format("{}: cannot open for reading ({})", path, std::strerror(errno)));
  }
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISDIR(st.st_mode)) {
    ::close(fd);
    throw ParseError(path, "", "is a folder; expected a file");
  }
  // Blocking reads from here: a pipe's writer is waited for, a FIFO without one gives end of file.
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  // libstdc++'s stdio_filebuf: a streambuf over a descriptor (closed with it).
  buffer_ = std::make_unique<__gnu_cxx::stdio_filebuf<char>>(fd, std::ios::in | std::ios::binary);
  stream_ = std::make_unique<std::istream>(buffer_.get());
}

InputFile::~InputFile() = default;
InputFile::InputFile(InputFile&&) noexcept = default;
InputFile& InputFile::operator=(InputFile&&) noexcept = default;

bool input_file_present(const std::filesystem::path& path, std::string_view what) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) return false;
  if (std::filesystem::is_regular_file(status)) return true;
  throw ParseError(
      path.string(), "",
      fmt::format("is {}; expected a file ({})",
                  std::filesystem::is_directory(status) ? "a folder" : "a device, pipe or socket",
                  what));
}

void require_input_file(const std::filesystem::path& path, std::string_view what) {
  if (!input_file_present(path, what))
    throw IoError(fmt::format("{}: missing ({})", path.string(), what));
}

}  // namespace wifislam
