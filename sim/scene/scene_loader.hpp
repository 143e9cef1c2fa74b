#pragma once
// Loading and validating scene files (YAML, `version: 1`). See scenes/README.md for the schema.
//
// Every problem is reported as a ParseError naming the file, line and column, the key path
// (e.g. `corridors[2].width_m`) and what was expected: unknown keys, wrong types, values out of
// range, references to missing nodes/corridors, a disconnected corridor graph, a route through a
// corridor that does not exist ... Nothing is silently defaulted except keys that are absent.

#include <optional>
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

/// Why `name` cannot be a scene's name, if it cannot: a name becomes part of folder names
/// (compare's datasets/<name>-seed<seed>), so it is up to 100 letters, digits, '_', '-' and '.',
/// starting with a letter or digit (no '/', no "..", nothing a shell or YAML treats specially).
/// The key is optional: an empty name is none.
std::optional<std::string> scene_name_problem(const std::string& name);

/// Checks the cross-references and ranges of a scene built in code (the loader calls it too).
/// Throws InvalidInputError naming the offending item.
void validate_scene(const Scene& scene);

/// How resolved_scene_yaml writes text values (names, ids, descriptions).
enum class TextQuoting {
  kPlain,           // as datasets' scene.yaml has them: the scene loader reads them as text
  kWhereAmbiguous,  // quoted where plain YAML would read a number, boolean or null ("007")
};

/// The scene as YAML with every key, defaults filled in (the "resolved scene" written into
/// datasets). Loading the output gives back an equal scene. A reader that types plain scalars
/// (Python's Scene.to_dict) asks for TextQuoting::kWhereAmbiguous, so a name "007" stays text.
std::string resolved_scene_yaml(const Scene& scene, TextQuoting quoting = TextQuoting::kPlain);

}  // namespace wifislam::sim::scene
