#pragma once
// manifest.json of a dataset: what made it (versions, parameters), what it holds (counts), and the
// SHA-256 of every file except the PNGs, whose hashes live in images.sha256 (listed here, so it
// is covered too). Keeping the per-image hashes out of the JSON keeps the manifest small and the
// reader's memory flat however long the dataset is; `sha256sum -c images.sha256` checks them
// without our tools.
//
//   {"format": "wifislam-dataset", "format_version": 1, "images": true,
//    "versions": {"wifislam": "0.1.0", ...}, "parameters": {...},
//    "counts": {"frames": 900, "wifi_scans": 12, ...},
//    "files": [{"path": "rgb.txt", "sha256": "...", "bytes": 1234}, ...]}

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace wifislam {

struct ManifestFile {
  std::string path;  // relative to the dataset folder, '/' separators
  std::string sha256;
  std::uint64_t bytes = 0;
};

struct DatasetManifest {
  int format_version = 1;
  bool images = true;  // false for --no-images datasets (poses, odometry and Wi-Fi only)
  /// false: depth images only, no colour (a study case's dataset, read by the evaluation alone);
  /// the key "colour_images" is written only then.
  bool colour_images = true;
  std::map<std::string, std::string> versions;
  std::string parameters_json = "{}";  // a JSON object, as the generator recorded it
  std::map<std::string, std::int64_t> counts;
  std::vector<ManifestFile> files;
};

/// Hashes one file of a dataset folder.
ManifestFile describe_dataset_file(const std::filesystem::path& folder,
                                   const std::string& relative);

/// The manifest as JSON text (2-space indent, keys in a fixed order, trailing newline).
std::string manifest_to_json(const DatasetManifest& manifest);
/// Throws IoError (unreadable) or ParseError (not JSON, not our format, missing keys).
DatasetManifest read_dataset_manifest(const std::filesystem::path& path);

/// Checks every listed file's size and SHA-256. Throws ParseError naming the first file that is
/// missing or differs ("manifest mismatch"), with a hint about --no-verify.
void verify_manifest_files(const std::filesystem::path& folder, const DatasetManifest& manifest);

/// One line of images.sha256 ("<hex>  <path>\n", as sha256sum writes it).
std::string format_checksum_line(const std::string& sha256_hex, const std::string& relative);

}  // namespace wifislam
