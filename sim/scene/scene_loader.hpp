#pragma once
// Loading and validating scene files (YAML, `version: 1`). See scenes/README.md for the schema.
//
// Every problem is reported as a ParseError naming the file, line and column, the key path
// (e.g. `corridors[2].width_m`) and what was expected: unknown keys, wrong types, values out of
// range, references to missing nodes/corridors, a disconnected corridor graph, a route through a
// corridor that does not exist ... Nothing is silently defaulted except keys that are absent.

#include <string>

#include "sim/scene/scene.hpp"

namespace wifislam::sim::scene {

/// Loads a scene file. Throws IoError (cannot read) or ParseError (anything wrong inside).
Scene load_scene_file(const std::string& path);

/// Loads a scene from YAML text; `source_name` is used in error messages in place of a path.
Scene load_scene_yaml(const std::string& yaml_text, const std::string& source_name);

/// A receiver device (radio_model/receiver_device.hpp) by `name_or_file`: text ending in .yaml or
/// .yml or holding a '/' is a device file (relative to `folder`, the scene's, when not absolute),
/// anything else a shipped device's name. A device file holds the keys of an inline device
/// (scenes/README.md). Throws InvalidInputError (unknown name, missing file), IoError or
/// ParseError (located in the device file).
radio_model::ReceiverDevice load_receiver_device(const std::string& name_or_file,
                                                 const std::string& folder = "");

/// Checks the cross-references and ranges of a scene built in code (the loader calls it too).
/// Throws InvalidInputError naming the offending item.
void validate_scene(const Scene& scene);

/// The scene as YAML with every key, defaults filled in (the "resolved scene" written into
/// datasets). Loading the output gives back an equal scene.
std::string resolved_scene_yaml(const Scene& scene);

}  // namespace wifislam::sim::scene
