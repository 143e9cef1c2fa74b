#pragma once
// One writer per study database: `<database>.lock`, kept beside it, held with flock while a run
// (or a merge into it) writes. flock on the database file itself would be unsafe: closing any
// descriptor of it drops SQLite's own fcntl locks.

#include <filesystem>

namespace wifislam::study {

class DatabaseLock {
 public:
  /// Takes `<database>.lock` (created when missing): exclusive to write the database, or
  /// `shared` to read it whole (a merge's shards: no run may write them meanwhile, several
  /// merges may read them). InvalidInputError when another process holds it the other way
  /// (naming `doing`, what this one was about to do); IoError when it cannot be made.
  DatabaseLock(const std::filesystem::path& database, const char* doing, bool shared = false);
  ~DatabaseLock();
  DatabaseLock(const DatabaseLock&) = delete;
  DatabaseLock& operator=(const DatabaseLock&) = delete;

  /// Whether some process holds `<database>.lock` now; false when there is none. Creates
  /// nothing.
  static bool is_held(const std::filesystem::path& database);

 private:
  int fd_ = -1;
};

}  // namespace wifislam::study
