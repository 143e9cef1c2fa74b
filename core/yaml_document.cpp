#include "core/yaml_document.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <yaml-cpp/depthguard.h>

#include "core/error.hpp"

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

YAML::Node load_yaml_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw ParseError(path, "", "is a folder; expected a YAML file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw IoError(fmt::format("{}: cannot open for reading ({})", path, std::strerror(errno)));
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw IoError(path + ": read error");
  return parse_yaml_document(buffer.str(), path);
}

}  // namespace wifislam
