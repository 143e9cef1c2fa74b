#pragma once
// Penetration loss of one wall, per material and frequency, from two cited sources:
//
// 1. 3GPP TR 38.901 V16.1.0 (Release 16), Table 7.4.3-1, material penetration loss
//    L = a + b f_GHz:
//      concrete       5    + 4    f   -> 14.6 dB at 2.4 GHz, 25.8 dB at 5.2 GHz
//      standard glass 2    + 0.2  f   ->  2.5 dB,             3.0 dB
//      wood           4.85 + 0.12 f   ->  5.1 dB,             5.5 dB   (closed door leaves)
//    (Table 7.4.3-1 of Release 16 has no plywood; its 1.03 + 0.17 f row arrived in a later
//    release.) The table is meant for building entry (outdoor to indoor): its concrete is an
//    exterior wall. It agrees with a 0.2 m concrete slab by 2. (14.6 against 14.6 dB at
//    2.4 GHz, 25.4 against 25.8 at 5.2 GHz, 27.5 against 28.2 at 5.8 GHz; tested within 1 dB),
//    so it is kept for concrete.
//
// 2. ITU-R P.2040-3 (2023), Table 3 material parameters, eta' = a f^b, sigma = c f^d S/m
//    (f in GHz), through the single-layer slab at normal incidence (P.2040-3 section 3):
//      eta = eta' - j 17.98 sigma / f,  n = sqrt(eta),  R = (1 - n) / (1 + n),
//      q = 2 pi f d n / c,  T = (1 - R^2) e^{-jq} / (1 - R^2 e^{-2jq}),  L = -20 log10 |T|.
//    Used for the two materials TR 38.901 does not have:
//      brick          a 3.91, sigma 0.0238 f^0.16: a solid masonry wall of the building's
//                     wall thickness (building.wall_thickness_m) -> 0.15 m: 4.2 dB at 2.4 GHz,
//                     5.0 dB at 5.2 GHz; 0.2 m: 5.8 and 6.2 dB
//      plasterboard   a 2.73, sigma 0.0085 f^0.9395: a stud partition of two 12.5 mm boards,
//                     the cavity lossless and the two boards' losses added (their mutual
//                     reflections are ignored) -> 2.2 dB at 2.4 and at 5.2 GHz (mostly
//                     reflection at the four surfaces; the boards absorb little)
//    COST 231's multi-wall figures (light wall 3.4 dB, heavy wall 6.9 dB at 1.8 GHz) are
//    higher: they were fitted to whole buildings, studs, ducts and furniture included, which our
//    explicit geometry does not have; P.2040 describes the material itself.

#include <array>

#include "sim/scene/scene.hpp"

namespace wifislam {

inline constexpr int kWallMaterialCount = 5;
inline int material_index(WallMaterial m) { return static_cast<int>(m); }

/// ITU-R P.2040-3 Table 3: relative permittivity a f^b and conductivity c f^d S/m, f in GHz.
struct P2040Material {
  double a = 1.0, b = 0.0, c = 0.0, d = 0.0;
};
inline constexpr P2040Material kP2040Brick{3.91, 0.0, 0.0238, 0.16};
inline constexpr P2040Material kP2040Plasterboard{2.73, 0.0, 0.0085, 0.9395};
inline constexpr P2040Material kP2040Concrete{5.24, 0.0, 0.0462, 0.7822};

/// Loss in dB of a slab of `thickness_m` at normal incidence (the formula above).
double p2040_slab_loss_db(const P2040Material& material, double thickness_m, double frequency_mhz);

/// One material's loss: a + b f_GHz, plus `layers` P.2040 slabs of `slab_thickness_m` when
/// `layers` > 0.
struct WallLossLaw {
  double a_db = 0.0;          // loss at 0 GHz (intercept)
  double b_db_per_ghz = 0.0;  // slope
  P2040Material slab;
  double slab_thickness_m = 0.0;
  int layers = 0;
  double at(double frequency_mhz) const;
  static WallLossLaw linear(double a_db, double b_db_per_ghz);
  static WallLossLaw slabs(const P2040Material& material, double thickness_m, int layers);
};

/// Loss laws for every material, indexed by material_index(). Defaults as documented above;
/// tests and studies may replace entries.
struct WallLossTable {
  /// The default laws for a building whose walls are `wall_thickness_m` thick.
  explicit WallLossTable(double wall_thickness_m);
  /// ... for the schema's default wall thickness, 0.15 m.
  WallLossTable() : WallLossTable(0.15) {}
  std::array<WallLossLaw, kWallMaterialCount> laws;
  double loss_db(WallMaterial material, double frequency_mhz) const {
    return laws[material_index(material)].at(frequency_mhz);
  }
};

}  // namespace wifislam
