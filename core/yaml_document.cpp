#include "core/yaml_document.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <yaml-cpp/depthguard.h>

#include "core/did_you_mean.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"

namespace wifislam {

namespace {

std::string where(const std::string& source, const YAML::Mark& mark) {
  if (mark.line < 0) return source;
  return fmt::format("{}:{}:{}", source, mark.line + 1, mark.column + 1);
}

/// Every mapping of the document, each once (an alias repeats its anchor's node, which sits at
/// the anchor's position, so the work stays bounded by the text's length), checked for keys given
/// twice.
void check_unique_keys(const YAML::Node& root, const std::string& source) {
  std::set<std::pair<int, int>> visited;  // (line, column) of every collection checked
  std::vector<std::pair<YAML::Node, std::string>> pending{{root, ""}};
  while (!pending.empty()) {
    const auto [node, path] = pending.back();
    pending.pop_back();
    if (!node.IsMap() && !node.IsSequence()) continue;
    if (!visited.emplace(node.Mark().line, node.Mark().column).second) continue;
    if (node.IsSequence()) {
      for (std::size_t i = 0; i < node.size(); ++i) {
        pending.emplace_back(node[i], fmt::format("{}[{}]", path, i));
      }
      continue;
    }
    std::map<std::string, YAML::Mark> keys;
    for (const auto& kv : node) {
      const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "";
      const std::string key_path = path.empty() ? key : path + "." + key;
      const auto [first, fresh] = keys.emplace(key, kv.first.Mark());
      if (!fresh) {
        throw ParseError(where(source, kv.first.Mark()), key_path,
                         fmt::format("duplicate key: '{}' is already given at line {} of this "
                                     "mapping; give each key once",
                                     key, first->second.line + 1));
      }
      pending.emplace_back(kv.second, key_path);
    }
  }
}

}  // namespace

YAML::Node parse_yaml_document(const std::string& text, const std::string& source_name) {
  if (text.size() > kMaxYamlDocumentBytes) {
    throw ParseError(source_name, "",
                     fmt::format("{} bytes; a YAML file (scene, study, system, calibration) is at "
                                 "most {} MiB (the YAML reader needs about 100 times a file's "
                                 "size in memory)",
                                 text.size(), kMaxYamlDocumentBytes >> 20));
  }
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::DeepRecursion& e) {
    // yaml-cpp's own message for this is "bad file".
    throw ParseError(where(source_name, e.mark), "",
                     "not valid YAML: lists or mappings nested deeper than the YAML reader "
                     "follows (hundreds of levels; these files need a handful)");
  } catch (const YAML::ParserException& e) {
    throw ParseError(where(source_name, e.mark), "", "not valid YAML: " + e.msg);
  }
  check_unique_keys(root, source_name);
  return root;
}

std::string read_yaml_text(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw ParseError(path, "", "is a folder; expected a YAML file");
  }
  InputFile file(path);  // never blocks in open() (a FIFO without a writer reads as empty)
  std::istream& in = file.stream();
  // Read at most one byte past the cap (a FIFO or /dev/zero has no size to check first).
  std::string text(kMaxYamlDocumentBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) throw IoError(path + ": read error");
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxYamlDocumentBytes) {
    std::error_code size_error;
    const auto bytes = std::filesystem::file_size(path, size_error);
    throw ParseError(
        path, "",
        fmt::format("{}; a YAML file (scene, study, system, calibration) is at most {} MiB (the "
                    "YAML reader needs about 100 times a file's size in memory)",
                    size_error ? std::string("larger than that") : fmt::format("{} bytes", bytes),
                    kMaxYamlDocumentBytes >> 20));
  }
  return text;
}

YAML::Node load_yaml_file(const std::string& path) {
  return parse_yaml_document(read_yaml_text(path), path);
}

std::string YamlReader::where(const YAML::Node& n) const {
  return wifislam::where(file_, n.Mark());
}

void YamlReader::fail(const YAML::Node& n, const std::string& key,
                      const std::string& message) const {
  throw ParseError(where(n), key, message);
}

void YamlReader::only_keys(const YAML::Node& map, const std::vector<std::string>& known,
                           const std::string& prefix) const {
  for (const auto& kv : map) {
    const std::string key = kv.first.Scalar();
    if (std::find(known.begin(), known.end(), key) == known.end()) {
      fail(kv.first, prefix + key, "unknown key" + did_you_mean(key, known));
    }
  }
}

std::string YamlReader::scalar(const YAML::Node& n, const std::string& key) const {
  if (!n.IsScalar()) fail(n, key, "expected a single value");
  return n.Scalar();
}

}  // namespace wifislam
