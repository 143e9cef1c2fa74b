#include "radio_model/wall_materials.hpp"

namespace wifislam {

std::array<WallLossLaw, kWallMaterialCount> WallLossTable::default_laws() {
  std::array<WallLossLaw, kWallMaterialCount> laws{};
  laws[material_index(WallMaterial::kPlasterboard)] = {3.4 - 0.12 * 2.4, 0.12};  // COST 231 light
  laws[material_index(WallMaterial::kBrick)] = {6.9 - 2.0 * 2.4, 2.0};           // COST 231 heavy
  laws[material_index(WallMaterial::kConcrete)] = {5.0, 4.0};    // TR 38.901 Table 7.4.3-1
  laws[material_index(WallMaterial::kGlass)] = {2.0, 0.2};       // TR 38.901 standard glass
  laws[material_index(WallMaterial::kWoodDoor)] = {4.85, 0.12};  // TR 38.901 wood
  return laws;
}

}  // namespace wifislam
