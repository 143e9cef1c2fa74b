#include "fuzz/dataset_bundle.hpp"

#include <algorithm>
#include <fstream>
#include <set>

namespace wifislam::fuzz {
namespace {

namespace fs = std::filesystem;

bool is_safe_name(std::string_view name) {
  if (name.empty() || name.size() > 96) return false;
  int components = 1;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= name.size(); ++i) {
    if (i < name.size() && name[i] != '/') {
      const char c = name[i];
      const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '.' || c == '_' || c == '-';
      if (!ok) return false;
      continue;
    }
    const std::string_view part = name.substr(start, i - start);
    if (part.empty() || part == "." || part == "..") return false;
    if (i < name.size() && ++components > 3) return false;
    start = i + 1;
  }
  return true;
}

// Positions where a marker line starts: offset 0, or just after a '\n'.
bool marker_at(std::string_view data, std::size_t pos) {
  return (pos == 0 || data[pos - 1] == '\n') &&
         data.substr(pos, kBundleMarker.size()) == kBundleMarker;
}

}  // namespace

std::vector<BundleFile> unpack_bundle(std::string_view data) {
  std::vector<BundleFile> files;
  std::set<std::string, std::less<>> seen;
  std::size_t pos = 0;
  while (pos < data.size() && !marker_at(data, pos)) {  // bytes before the first marker: ignored
    const std::size_t eol = data.find('\n', pos);
    pos = eol == std::string_view::npos ? data.size() : eol + 1;
  }
  while (pos < data.size()) {
    const std::size_t name_start = pos + kBundleMarker.size();
    const std::size_t name_end = std::min(data.find('\n', name_start), data.size());
    const std::string_view name = data.substr(name_start, name_end - name_start);
    std::size_t content_start = std::min(name_end + 1, data.size());
    std::size_t next = content_start;
    while (next < data.size() && !marker_at(data, next)) {
      const std::size_t eol = data.find('\n', next);
      next = eol == std::string_view::npos ? data.size() : eol + 1;
    }
    // The newline before a marker separates sections; it is not part of the file.
    const std::size_t content_end = next < data.size() ? next - 1 : next;
    if (is_safe_name(name) && seen.insert(std::string(name)).second) {
      files.push_back(
          {std::string(name),
           data.substr(content_start, std::max(content_end, content_start) - content_start)});
    }
    pos = next;
  }
  return files;
}

void write_bundle_files(const std::vector<BundleFile>& files, const fs::path& folder) {
  for (const BundleFile& file : files) {
    const fs::path path = folder / file.name;
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    if (ec) continue;  // a name that is both a file and a folder: the later one is skipped
    std::ofstream out(path, std::ios::binary);
    out.write(file.bytes.data(), static_cast<std::streamsize>(file.bytes.size()));
  }
}

}  // namespace wifislam::fuzz
