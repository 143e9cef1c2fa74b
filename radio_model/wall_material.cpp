#include "radio_model/wall_material.hpp"

namespace wifislam::radio_model {

const char* to_string(WallMaterial material) {
  switch (material) {
    case WallMaterial::kPlasterboard:
      return "plasterboard";
    case WallMaterial::kBrick:
      return "brick";
    case WallMaterial::kConcrete:
      return "concrete";
    case WallMaterial::kGlass:
      return "glass";
    case WallMaterial::kWoodDoor:
      return "wood_door";
  }
  return "unknown";
}

std::optional<WallMaterial> wall_material_from_string(const std::string& name) {
  for (WallMaterial m : {WallMaterial::kPlasterboard, WallMaterial::kBrick, WallMaterial::kConcrete,
                         WallMaterial::kGlass, WallMaterial::kWoodDoor}) {
    if (name == to_string(m)) return m;
  }
  return std::nullopt;
}

}  // namespace wifislam::radio_model
