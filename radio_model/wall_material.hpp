#pragma once
// The physical materials a wall (and, for the radio, a door leaf) is made of. The radio model maps
// each to a per-band penetration loss (wall_materials.hpp); the scene names them
// (sim/scene/scene.hpp) and the world tags every wall face with one.

#include <optional>
#include <string>

namespace wifislam::radio_model {

enum class WallMaterial { kPlasterboard, kBrick, kConcrete, kGlass, kWoodDoor };
inline constexpr int kWallMaterialCount = 5;
inline int material_index(WallMaterial m) { return static_cast<int>(m); }

/// The scene file's name of a material ("plasterboard", "brick", "concrete", "glass", "wood_door").
const char* to_string(WallMaterial material);
std::optional<WallMaterial> wall_material_from_string(const std::string& name);

}  // namespace wifislam::radio_model
