#pragma once
// Parsing a YAML document (scene files, calibration.yaml) with located errors. yaml-cpp on its own
// keeps the first of two equal keys in a mapping silently and reports nesting beyond its depth
// limit as "bad file"; here both are ParseErrors naming "file:line:column" and the key path.

#include <string>

#include <yaml-cpp/yaml.h>

namespace wifislam {

/// Parses `text` (read from `source_name`, used in messages). Throws ParseError for invalid YAML,
/// collections nested deeper than yaml-cpp allows, and a key given twice in one mapping (naming
/// the second occurrence and the line of the first).
YAML::Node parse_yaml_document(const std::string& text, const std::string& source_name);

/// Reads and parses a YAML file. Throws IoError when it cannot be read, ParseError (exit 2 on the
/// command line) when `path` is a folder or the text is not a valid document.
YAML::Node load_yaml_file(const std::string& path);

}  // namespace wifislam
