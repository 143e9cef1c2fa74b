#pragma once
// Scene keys by path, for tools that set one key of a scene at a time (study axes): the list of
// every key the schema knows, and setting a key in a scene's YAML before it is loaded (so that
// the loader's checks and ranges apply to the new value as to any other).
//
// Paths are the loader's key paths: "access_points.count", "radio.shadowing_sigma_db",
// "route.pause.spacing_m". An element of a list is "corridors[2].material"; "corridors[*].material"
// stands for every element.

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace wifislam::sim::scene {

/// Every key path of the scene schema, list elements written "[*]", in schema order.
const std::vector<std::string>& scene_key_paths();

/// `path` with every list index written "[*]" ("corridors[2].material" -> "corridors[*].material").
std::string generic_key_path(const std::string& path);

/// Whether `path` names a key of the schema (any index, or [*]).
bool is_scene_key_path(const std::string& path);

/// Sets the key at `path` in `root` (a scene file's YAML) to `value`, creating the mappings on
/// the way; "[*]" sets it in every element of the list, "[k]" in element k. Throws
/// InvalidInputError when a list in the path is missing or too short for the index.
void set_scene_key(YAML::Node root, const std::string& path, const YAML::Node& value);

}  // namespace wifislam::sim::scene
