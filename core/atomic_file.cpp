#include "core/atomic_file.hpp"

#include <openssl/evp.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <system_error>

#include "core/error.hpp"
#include "core/output_folder.hpp"

namespace wifislam {

namespace fs = std::filesystem;

void write_file_atomic(const fs::path& path, std::string_view contents) {
  const fs::path tmp = path.string() + ".partial";
  {
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
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw IoError(path.string() + ": cannot rename temporary file into place: " + ec.message());
  }
}

AtomicDirectory::AtomicDirectory(fs::path final_path, bool overwrite) : overwrite_(overwrite) {
  if (final_path.empty()) throw InvalidInputError("output folder: the path is empty");
  final_ = resolve_path(final_path);
  std::error_code ec;
  if (fs::exists(final_, ec)) {
    if (!fs::is_directory(final_, ec)) {
      throw InvalidInputError(final_.string() + ": exists and is not a folder");
    }
    if (!overwrite_) {
      throw InvalidInputError(final_.string() + ": already exists (pass --force to replace it)");
    }
    check_folder_replaceable(final_);
  }
  staging_ = final_.string() + ".partial";
  if (fs::exists(fs::symlink_status(staging_, ec))) {
    // Left over from an interrupted run: ours (it carries the marker from the start) or empty.
    if (!fs::is_directory(fs::symlink_status(staging_, ec)) ||
        !(fs::is_empty(staging_, ec) || looks_like_tool_output(staging_))) {
      throw InvalidInputError(staging_.string() +
                              ": exists and is not an unfinished wifislam output; remove it or "
                              "choose another output folder");
    }
    fs::remove_all(staging_, ec);
  }
  fs::create_directories(staging_, ec);
  if (ec) throw IoError(staging_.string() + ": cannot create folder: " + ec.message());
  try {
    write_file_atomic(staging_ / kOutputMarkerFile,
                      "Written by wifislam. `--force` may replace this folder.\n");
  } catch (...) {
    fs::remove_all(staging_, ec);
    throw;
  }
}

AtomicDirectory::~AtomicDirectory() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(staging_, ec);
  }
}

void AtomicDirectory::commit() {
  std::error_code ec;
  fs::path set_aside;  // the folder being replaced, until the new one is in place
  if (fs::exists(final_, ec)) {
    if (!overwrite_) throw InvalidInputError(final_.string() + ": already exists");
    if (!fs::is_directory(final_, ec)) {
      throw InvalidInputError(final_.string() + ": exists and is not a folder");
    }
    check_folder_replaceable(final_);
    set_aside = final_.string() + ".replaced";
    if (fs::exists(fs::symlink_status(set_aside, ec))) {
      if (!fs::is_directory(fs::symlink_status(set_aside, ec)) ||
          !(fs::is_empty(set_aside, ec) || looks_like_tool_output(set_aside))) {
        throw InvalidInputError(set_aside.string() +
                                ": exists and is not a replaced wifislam output; remove it");
      }
      fs::remove_all(set_aside, ec);
    }
    fs::rename(final_, set_aside, ec);
    if (ec) throw IoError(final_.string() + ": cannot replace: " + ec.message());
  }
  fs::rename(staging_, final_, ec);
  if (ec) {
    const std::string message = ec.message();
    if (!set_aside.empty()) fs::rename(set_aside, final_, ec);
    throw IoError(final_.string() + ": cannot move finished folder into place: " + message);
  }
  committed_ = true;
  if (!set_aside.empty()) fs::remove_all(set_aside, ec);
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
