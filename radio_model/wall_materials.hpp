#pragma once
// Penetration loss of one wall, per material and frequency.
//
// Each material's loss is linear in frequency, L(f) = a + b f_GHz, the form of 3GPP TR 38.901
// V16.1.0, Table 7.4.3-1 (building penetration loss of materials):
//   concrete       5    + 4    f   -> 14.6 dB at 2.4 GHz, 25.8 dB at 5.2 GHz
//   standard glass 2    + 0.2  f   ->  2.5 dB,             3.0 dB
//   wood           4.85 + 0.12 f   ->  5.1 dB,             5.5 dB   (wooden door leaf)
// TR 38.901 has no plasterboard or brick, so those two are anchored at 2.4 GHz on the COST 231
// multi-wall model (COST Action 231 final report, sec. 4.7.2: light wall 3.4 dB, heavy wall
// 6.9 dB) and given the slope of the nearest 38.901 material:
//   plasterboard   3.11 + 0.12 f   ->  3.4 dB,             3.7 dB   (light wall; wood's slope:
//                  light low-permittivity boards change little with frequency)
//   brick          2.1  + 2.0  f   ->  6.9 dB,            12.5 dB   (heavy wall; masonry like
//                  concrete but an interior brick partition is thinner, so half its slope)
// These match the usual Wi-Fi survey figures (drywall 3-4 dB, brick 8 dB, concrete 10-15 dB at
// 2.4 GHz, higher at 5 GHz for the heavy materials).

#include <array>

#include "sim/scene/scene.hpp"

namespace wifislam {

inline constexpr int kWallMaterialCount = 5;
inline int material_index(WallMaterial m) { return static_cast<int>(m); }

struct WallLossLaw {
  double a_db = 0.0;          // loss at 0 GHz (intercept)
  double b_db_per_ghz = 0.0;  // slope
  double at(double frequency_mhz) const { return a_db + b_db_per_ghz * frequency_mhz * 1e-3; }
};

/// Loss laws for every material, indexed by material_index(). Defaults as documented above;
/// tests and studies may replace entries.
struct WallLossTable {
  std::array<WallLossLaw, kWallMaterialCount> laws = default_laws();
  double loss_db(WallMaterial material, double frequency_mhz) const {
    return laws[material_index(material)].at(frequency_mhz);
  }
  static std::array<WallLossLaw, kWallMaterialCount> default_laws();
};

}  // namespace wifislam
