#pragma once
// Parsing a YAML document (scene files, calibration.yaml) with located errors. yaml-cpp on its own
// keeps the first of two equal keys in a mapping silently and reports nesting beyond its depth
// limit as "bad file"; here both are ParseErrors naming "file:line:column" and the key path.

#include <cstddef>
#include <string>

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

/// Reads and parses a YAML file. Throws IoError when it cannot be read, ParseError (exit 2 on the
/// command line) when `path` is a folder or the text is not a valid document.
YAML::Node load_yaml_file(const std::string& path);

}  // namespace wifislam
