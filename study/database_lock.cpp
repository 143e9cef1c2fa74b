#include "study/database_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "core/error.hpp"

namespace wifislam::study {

namespace {

std::filesystem::path lock_path(const std::filesystem::path& database) {
  return database.string() + ".lock";
}

}  // namespace

DatabaseLock::DatabaseLock(const std::filesystem::path& database, const char* doing, bool shared) {
  const std::filesystem::path lock = lock_path(database);
  std::error_code ec;
  if (std::filesystem::is_directory(lock, ec)) {
    throw InvalidInputError(fmt::format(
        "{}: a folder where the database's lock file goes; move it away", lock.string()));
  }
  fd_ = ::open(lock.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    throw IoError(
        fmt::format("{}: cannot create the lock ({})", lock.string(), std::strerror(errno)));
  }
  if (::flock(fd_, (shared ? LOCK_SH : LOCK_EX) | LOCK_NB) != 0) {
    ::close(fd_);
    if (shared) {
      throw InvalidInputError(
          fmt::format("{}: a run is writing it now (it holds {}); not {} it until that run is done",
                      database.string(), lock.string(), doing));
    }
    throw InvalidInputError(fmt::format(
        "{}: another run is writing this database now (it holds {}); not {} it. Wait for that "
        "run to finish, or give each run a database of its own (--shard i/N and study merge)",
        database.string(), lock.string(), doing));
  }
}

DatabaseLock::~DatabaseLock() { ::close(fd_); }

bool DatabaseLock::is_held(const std::filesystem::path& database) {
  const int fd = ::open(lock_path(database).c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool held = ::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(fd);
  return held;
}

}  // namespace wifislam::study
