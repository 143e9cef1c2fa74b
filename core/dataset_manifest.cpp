#include "core/dataset_manifest.hpp"

#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/dataset_format.hpp"
#include "core/error.hpp"

namespace wifislam {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

ManifestFile describe_dataset_file(const fs::path& folder, const std::string& relative) {
  const fs::path file = folder / relative;
  std::error_code ec;
  const auto size = fs::file_size(file, ec);
  if (ec) throw IoError(file.string() + ": cannot read file size: " + ec.message());
  return {relative, sha256_file_hex(file), static_cast<std::uint64_t>(size)};
}

std::string manifest_to_json(const DatasetManifest& m) {
  ordered_json doc;
  doc["format"] = dataset::kFormatName;
  doc["format_version"] = m.format_version;
  doc["images"] = m.images;
  if (!m.colour_images) doc["colour_images"] = false;
  doc["versions"] = ordered_json::object();
  for (const auto& [k, v] : m.versions) doc["versions"][k] = v;
  doc["parameters"] = ordered_json::parse(m.parameters_json);
  doc["counts"] = ordered_json::object();
  for (const auto& [k, v] : m.counts) doc["counts"][k] = v;
  doc["files"] = ordered_json::array();
  for (const ManifestFile& f : m.files) {
    doc["files"].push_back({{"path", f.path}, {"sha256", f.sha256}, {"bytes", f.bytes}});
  }
  return doc.dump(2) + "\n";
}

DatasetManifest read_dataset_manifest(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path.string() + ": cannot open file for reading");
  std::stringstream text;
  text << in.rdbuf();
  ordered_json doc;
  try {
    doc = ordered_json::parse(text.str());
  } catch (const nlohmann::json::parse_error& e) {
    throw ParseError(path.string(), "", std::string("not valid JSON: ") + e.what());
  }
  const std::string where = path.string();
  auto require = [&](const char* key) -> const ordered_json& {
    if (!doc.is_object() || !doc.contains(key))
      throw ParseError(where, key, std::string("missing key '") + key + "'");
    return doc[key];
  };
  try {
    if (require("format").get<std::string>() != dataset::kFormatName) {
      throw ParseError(
          where, "format",
          fmt::format("format is '{}', expected '{}'", doc["format"].dump(), dataset::kFormatName));
    }
    DatasetManifest m;
    m.format_version = require("format_version").get<int>();
    if (m.format_version != dataset::kFormatVersion) {
      throw ParseError(where, "format_version",
                       fmt::format("format_version {} is not supported (this build reads {})",
                                   m.format_version, dataset::kFormatVersion));
    }
    m.images = require("images").get<bool>();
    if (doc.contains("colour_images")) m.colour_images = doc["colour_images"].get<bool>();
    for (const auto& [k, v] : require("versions").items()) m.versions[k] = v.get<std::string>();
    m.parameters_json = require("parameters").dump();
    for (const auto& [k, v] : require("counts").items()) m.counts[k] = v.get<std::int64_t>();
    for (const auto& f : require("files")) {
      m.files.push_back({f.at("path").get<std::string>(), f.at("sha256").get<std::string>(),
                         f.at("bytes").get<std::uint64_t>()});
    }
    return m;
  } catch (const nlohmann::json::exception& e) {
    throw ParseError(where, "", std::string("unexpected manifest content: ") + e.what());
  }
}

void verify_manifest_files(const fs::path& folder, const DatasetManifest& manifest) {
  const std::string manifest_path = (folder / dataset::kManifest).string();
  for (const ManifestFile& f : manifest.files) {
    const fs::path file = folder / f.path;
    std::error_code ec;
    const auto size = fs::file_size(file, ec);
    if (ec) {
      throw ParseError(file.string(), "",
                       fmt::format("listed in {} but missing (manifest mismatch)", manifest_path));
    }
    if (size != f.bytes || sha256_file_hex(file) != f.sha256) {
      throw ParseError(
          file.string(), "",
          fmt::format("contents differ from {} (manifest mismatch: {} bytes, expected {}); the "
                      "file was changed after generation; use --no-verify to read it anyway",
                      manifest_path, size, f.bytes));
    }
  }
}

std::string format_checksum_line(const std::string& sha256_hex, const std::string& relative) {
  return sha256_hex + "  " + relative + "\n";
}

}  // namespace wifislam
