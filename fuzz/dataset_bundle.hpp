#pragma once
// A dataset folder packed into one fuzz input, so the fuzzer can change any of its files, and
// several at once. Sections follow each other; a section is a marker line naming the file and
// the file's bytes up to the newline before the next marker line (that newline separates the
// sections and is not part of the file), or up to the end:
//
//   === rgb.txt
//   0.000000 rgb/0.000000.png
//   === rgb/0.000000.png
//   <PNG bytes>
//
// Names are relative paths of at most three components made of [A-Za-z0-9._-], no `..`; a
// section with any other name is skipped (the fuzzer mutates names too), as is a repeated name.
// scripts/fuzz.sh packs the seed datasets.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace wifislam::fuzz {

inline constexpr std::string_view kBundleMarker = "=== ";

struct BundleFile {
  std::string name;
  std::string_view bytes;
};

/// Splits a bundle into its files (views into `data`).
std::vector<BundleFile> unpack_bundle(std::string_view data);

/// Writes the files of a bundle into `folder`, which must exist and be empty.
void write_bundle_files(const std::vector<BundleFile>& files, const std::filesystem::path& folder);

}  // namespace wifislam::fuzz
