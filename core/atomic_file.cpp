#include "core/atomic_file.hpp"

#include <fcntl.h>
#include <openssl/evp.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string_view>
#include <system_error>

#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "core/stop_signal.hpp"

namespace wifislam {

namespace fs = std::filesystem;

namespace {

// An exclusive lock on a folder (flock on its descriptor), without waiting: the descriptor, or
// -1 when another process holds the lock or the folder cannot be opened.
int lock_folder(const fs::path& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return -1;
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

// A marker file made in place (no `<file>.partial` and rename, which a kill could leave half
// done): only its existence matters.
void create_marker(const fs::path& file, std::string_view text) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) throw IoError(file.string() + ": cannot create: " + std::strerror(errno));
  const bool written = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  ::close(fd);
  if (!written) throw IoError(file.string() + ": write failed");
}

// Whether the open descriptor `fd` is the folder now at `path`.
bool same_folder(int fd, const fs::path& path) {
  struct stat open_one {
  }, at_path{};
  return ::fstat(fd, &open_one) == 0 && ::stat(path.c_str(), &at_path) == 0 &&
         open_one.st_dev == at_path.st_dev && open_one.st_ino == at_path.st_ino;
}

}  // namespace

namespace {

// The partial file of write_file_atomic, shared with write_files_atomic.
fs::path partial_of(const fs::path& path) { return path.string() + ".partial"; }

void write_partial(const fs::path& path, std::string_view contents) {
  const fs::path tmp = partial_of(path);
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  if (!out) throw IoError(path.string() + ": cannot open for writing");
  out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
  out.flush();
  if (!out) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw IoError(path.string() + ": write failed");
  }
}

void rename_partial_into_place(const fs::path& path) {
  std::error_code ec;
  fs::rename(partial_of(path), path, ec);
  if (ec) {
    fs::remove(partial_of(path), ec);
    throw IoError(path.string() + ": cannot rename temporary file into place: " + ec.message());
  }
}

}  // namespace

void write_file_atomic(const fs::path& path, std::string_view contents) {
  check_file_replaceable(path);
  write_partial(path, contents);
  rename_partial_into_place(path);
}

void write_files_atomic(const std::vector<std::pair<fs::path, std::string_view>>& files) {
  for (const auto& [path, contents] : files) check_file_replaceable(path);
  std::size_t written = 0;
  try {
    for (; written < files.size(); ++written)
      write_partial(files[written].first, files[written].second);
  } catch (...) {
    std::error_code ec;
    for (std::size_t i = 0; i < written; ++i) fs::remove(partial_of(files[i].first), ec);
    throw;
  }
  for (const auto& [path, contents] : files) rename_partial_into_place(path);
}

AtomicDirectory::AtomicDirectory(fs::path final_path, bool overwrite) : overwrite_(overwrite) {
  if (final_path.empty()) throw InvalidInputError("output folder: the path is empty");
  std::error_code ec;
  // Resolving a link named as the output would replace the folder it points to, wherever that
  // is: an external system that left `eval` as a link in its run folder made the evaluation
  // replace the link's target. Commands refuse links first (check_output_folder); every writer
  // of a folder comes here.
  if (const fs::path link = link_named_by(final_path); !link.empty()) {
    throw InvalidInputError(link.string() +
                            ": is a symbolic link; refusing to write or replace a folder "
                            "through it");
  }
  final_ = resolve_path(final_path);
  if (fs::exists(final_, ec)) {
    if (!fs::is_directory(final_, ec)) {
      throw InvalidInputError(final_.string() + ": exists and is not a folder");
    }
    if (!overwrite_) {
      throw InvalidInputError(final_.string() + ": already exists (pass --force to replace it)");
    }
    check_folder_replaceable(final_);
  }
  // Before the work: what is beside the output must be ours to remove when the time comes.
  check_folders_beside(final_);
  staging_ = staging_path_of(final_);
  const std::string busy =
      final_.string() + ": another wifislam run is writing this folder now (into " +
      staging_.string() + "); wait for it to finish or choose another output folder";
  if (fs::exists(fs::symlink_status(staging_, ec))) {
    // Left over from an interrupted run (check_folders_beside: empty, or with the unfinished
    // marker), or being written by a run now, which holds its lock: then it is left alone.
    const int leftover = lock_folder(staging_);
    if (leftover < 0) throw InvalidInputError(busy);
    const std::string failed = remove_folder_marker_last(staging_, kUnfinishedMarkerFile);
    ::close(leftover);
    if (!failed.empty()) {
      throw IoError(staging_.string() + ": left by an interrupted run, and it cannot be removed (" +
                    failed + "); remove it yourself");
    }
  }
  for (fs::path p = final_.parent_path(); p.has_relative_path() && !fs::exists(p, ec);
       p = p.parent_path())
    created_parent_ = p;
  fs::create_directories(final_.parent_path(), ec);
  bool created = fs::create_directory(staging_, ec);
  if (!created && ec == std::errc::no_such_file_or_directory) {
    // A run abandoned beside this one removed the new parent they shared: make it again.
    fs::create_directories(final_.parent_path(), ec);
    created = fs::create_directory(staging_, ec);
  }
  if (!created) {
    remove_created_parents();
    if (ec) throw IoError(staging_.string() + ": cannot create folder: " + ec.message());
    throw InvalidInputError(busy);  // another run created it since
  }
  // Held until the folder is committed or removed; the same folder (not one made in its place
  // by another run in between) must be the one locked.
  lock_fd_ = lock_folder(staging_);
  if (lock_fd_ < 0 || !same_folder(lock_fd_, staging_)) {
    if (lock_fd_ >= 0) ::close(lock_fd_);
    lock_fd_ = -1;
    remove_created_parents();
    throw InvalidInputError(busy);
  }
  try {
    create_marker(staging_ / kUnfinishedMarkerFile,
                  "Being written by wifislam, or left unfinished by a run that was "
                  "interrupted; the next run into the same output removes it.\n");
    write_file_atomic(staging_ / kOutputMarkerFile,
                      "Written by wifislam. `--force` may replace this folder.\n");
  } catch (...) {
    fs::remove_all(staging_, ec);
    ::close(lock_fd_);
    remove_created_parents();
    throw;
  }
}

void AtomicDirectory::remove_created_parents() {
  // Innermost first; fs::remove takes only an empty folder, so one that something else has
  // written into since stays, and with it every folder above it.
  if (created_parent_.empty()) return;
  std::error_code ec;
  for (fs::path p = final_.parent_path(); fs::remove(p, ec) && p != created_parent_;
       p = p.parent_path()) {
  }
}

AtomicDirectory::~AtomicDirectory() {
  if (!committed_) {
    remove_folder_marker_last(staging_, kUnfinishedMarkerFile);
    remove_created_parents();
  }
  if (lock_fd_ >= 0) ::close(lock_fd_);
}

void AtomicDirectory::commit() {
  // The last point where a command stopped by Ctrl-C can still leave nothing (core/stop_signal).
  throw_if_stop_requested();
  std::error_code ec;
  fs::path set_aside;  // the folder being replaced, until the new one is in place
  if (fs::is_symlink(fs::symlink_status(final_, ec))) {
    throw InvalidInputError(final_.string() +
                            ": became a symbolic link while the output was written; refusing "
                            "to replace a folder through it");
  }
  if (fs::exists(final_, ec)) {
    if (!overwrite_) throw InvalidInputError(final_.string() + ": already exists");
    if (!fs::is_directory(final_, ec)) {
      throw InvalidInputError(final_.string() + ": exists and is not a folder");
    }
    check_folder_replaceable(final_);
    set_aside = set_aside_path_of(final_);
    check_set_aside_free(final_);  // again: one may have come since the work began
    // Empty, or a deletion that was cut short: finished now.
    if (fs::exists(set_aside, ec)) {
      if (const std::string failed = remove_folder_marker_last(set_aside, kDiscardedMarkerFile);
          !failed.empty()) {
        throw IoError(set_aside.string() + ": cannot be removed (" + failed + "), and replacing " +
                      final_.string() + " needs its place");
      }
    }
    fs::rename(final_, set_aside, ec);
    if (ec) throw IoError(final_.string() + ": cannot replace: " + ec.message());
  }
  // From here on the folder is finished: nothing may take it for a leftover once in place.
  // Removed last of all, so that a kill before this point leaves a leftover the next run removes.
  if (!fs::remove(staging_ / kUnfinishedMarkerFile, ec) && ec) {
    const std::string message = ec.message();
    if (!set_aside.empty()) fs::rename(set_aside, final_, ec);
    throw IoError((staging_ / kUnfinishedMarkerFile).string() + ": cannot remove: " + message);
  }
  fs::rename(staging_, final_, ec);
  if (ec) {
    const std::string message = ec.message();
    if (!set_aside.empty()) fs::rename(set_aside, final_, ec);
    throw IoError(final_.string() + ": cannot move finished folder into place: " + message);
  }
  committed_ = true;
  if (!set_aside.empty()) {
    // Marked first, so that a deletion cut short (a second Ctrl-C) is finished by the next run.
    try {
      create_marker(set_aside / kDiscardedMarkerFile, "Replaced by a newer output; deleted.\n");
    } catch (const Error&) {
      // Not markable (read-only?): deleted all the same; only a cut-short deletion would stay.
    }
    remove_folder_marker_last(set_aside, kDiscardedMarkerFile);
  }
  if (lock_fd_ >= 0) ::close(lock_fd_);
  lock_fd_ = -1;
}

namespace {
std::string to_hex(const unsigned char* digest, unsigned int size) {
  static const char* kHex = "0123456789abcdef";
  std::string out;
  for (unsigned int i = 0; i < size; ++i) {
    out += kHex[digest[i] >> 4];
    out += kHex[digest[i] & 0xF];
  }
  return out;
}
}  // namespace

std::string sha256_hex(std::string_view bytes) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int size = 0;
  EVP_Digest(bytes.data(), bytes.size(), digest, &size, EVP_sha256(), nullptr);
  return to_hex(digest, size);
}

std::string sha256_file_hex(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path.string() + ": cannot open for hashing");
  EVP_MD_CTX* ctx = EVP_MD_CTX_new();
  EVP_DigestInit_ex(ctx, EVP_sha256(), nullptr);
  std::array<char, 1 << 16> buf;
  while (in) {
    in.read(buf.data(), buf.size());
    EVP_DigestUpdate(ctx, buf.data(), static_cast<std::size_t>(in.gcount()));
  }
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int size = 0;
  EVP_DigestFinal_ex(ctx, digest, &size);
  EVP_MD_CTX_free(ctx);
  return to_hex(digest, size);
}

}  // namespace wifislam
