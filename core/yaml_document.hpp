#pragma once
// Parsing a YAML document (scene files, calibration.yaml) with located errors. yaml-cpp on its own
// keeps the first of two equal keys in a mapping silently and reports nesting beyond its depth
// limit as "bad file"; here both are ParseErrors naming "file:line:column" and the key path.

#include <cstddef>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace wifislam {

/// The largest YAML document read. yaml-cpp's node tree takes about 100 times the text's size
/// (a 50 MB scene took 4.8 GB); our files are a few kB, so 4 MiB leaves room for thousands of
/// explicit access points while bounding memory to about 400 MB.
inline constexpr std::size_t kMaxYamlDocumentBytes = std::size_t{4} << 20;

/// Parses `text` (read from `source_name`, used in messages). Throws ParseError for text longer
/// than kMaxYamlDocumentBytes, invalid YAML, collections nested deeper than yaml-cpp allows, and a
/// key given twice in one mapping (naming the second occurrence and the line of the first).
YAML::Node parse_yaml_document(const std::string& text, const std::string& source_name);

/// A YAML file's text, as load_yaml_file reads it: never blocking on a FIFO, at most
/// kMaxYamlDocumentBytes (ParseError beyond, and for a folder), IoError when it cannot be read.
/// For a caller that needs the bytes too (a study file's hash is its identity).
std::string read_yaml_text(const std::string& path);

/// Reads and parses a YAML file. Throws IoError when it cannot be read, ParseError (exit 2 on the
/// command line) when `path` is a folder or the text is not a valid document.
YAML::Node load_yaml_file(const std::string& path);

/// Reading a parsed document's fields with located errors: each names "file:line:column" and the
/// key path (study files, system files).
class YamlReader {
 public:
  explicit YamlReader(std::string file) : file_(std::move(file)) {}

  /// "file:line:column" of a node (just "file" when the node has no position).
  std::string where(const YAML::Node& n) const;
  /// Throws ParseError(where(n), key, message).
  [[noreturn]] void fail(const YAML::Node& n, const std::string& key,
                         const std::string& message) const;
  /// Fails on the first key of `map` not in `known`, naming the closest known one.
  void only_keys(const YAML::Node& map, const std::vector<std::string>& known,
                 const std::string& prefix) const;
  /// The node's text; fails when it is not a single value.
  std::string scalar(const YAML::Node& n, const std::string& key) const;

 private:
  std::string file_;
};

}  // namespace wifislam
