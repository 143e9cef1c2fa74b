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
// 2. For the two materials TR 38.901 does not have, a measured wall loss and a material's
//    frequency dependence:
//      L(f) = L_COST231 + A(f) - A(1.8 GHz),
//    L_COST231 the COST 231 multi-wall model's loss of a real wall at 1800 MHz (COST Action 231
//    final report, 1999, section 4.7.2: light wall 3.4 dB, heavy wall 6.9 dB; fitted to whole
//    walls of real buildings, studs, ducts and plaster included), and A(f) the absorption of
//    the wall's material, from ITU-R P.2040-3 (2023) Table 3 (eta' = a f^b, sigma = c f^d S/m,
//    f in GHz) through the slab formula of P.2040-3 section 3:
//      eta = eta' - j 17.98 sigma / f,  n = sqrt(eta),  A = 20 log10(e) (2 pi f / c) |Im n| d.
//      brick          a 3.91, sigma 0.0238 f^0.16, d the building's wall thickness
//                     (building.wall_thickness_m): 0.15 m -> 6.9 dB at 1.8 GHz, 7.0 at 2.4,
//                     7.5 at 5.2 (heavy wall)
//      plasterboard   a 2.73, sigma 0.0085 f^0.9395, two 12.5 mm boards of a stud partition
//                     -> 3.4 dB at 1.8 GHz, 3.5 at 2.4, 4.0 at 5.2 (light wall)
//    The slab's full transmission (p2040_slab_loss_db, reflections included) is not used for
//    these two: for an ideal homogeneous slab it gives 4.2 dB for 0.15 m of brick and 2.2 dB
//    for two boards at 2.4 GHz, below what walls of real buildings are measured to take, and
//    it oscillates with frequency (interference inside a perfectly flat slab) where real walls
//    do not. Its absorption term is the part that carries over.

#include <array>

#include "radio_model/wall_material.hpp"

namespace wifislam::radio_model {

/// ITU-R P.2040-3 Table 3: relative permittivity a f^b and conductivity c f^d S/m, f in GHz.
struct P2040Material {
  double a = 1.0, b = 0.0, c = 0.0, d = 0.0;
};
inline constexpr P2040Material kP2040Brick{3.91, 0.0, 0.0238, 0.16};
inline constexpr P2040Material kP2040Plasterboard{2.73, 0.0, 0.0085, 0.9395};
inline constexpr P2040Material kP2040Concrete{5.24, 0.0, 0.0462, 0.7822};

/// Transmission loss in dB of a homogeneous slab of `thickness_m` at normal incidence (P.2040-3
/// section 3: interfaces, internal echoes and absorption):
///   R = (1 - n) / (1 + n), q = 2 pi f d n / c, T = (1 - R^2) e^{-jq} / (1 - R^2 e^{-2jq}).
double p2040_slab_loss_db(const P2040Material& material, double thickness_m, double frequency_mhz);
/// Its absorption alone: 20 log10(e) (2 pi f / c) |Im n| d.
double p2040_absorption_db(const P2040Material& material, double thickness_m, double frequency_mhz);

/// One material's loss: a + b f_GHz (linear), or anchor_db at anchor_mhz plus the absorption
/// of `material` over `thickness_m` relative to its absorption at anchor_mhz (anchored).
struct WallLossLaw {
  double a_db = 0.0;          // loss at 0 GHz (intercept)
  double b_db_per_ghz = 0.0;  // slope
  bool anchored = false;
  double anchor_db = 0.0, anchor_mhz = 0.0;
  P2040Material material;
  double thickness_m = 0.0;
  double at(double frequency_mhz) const;
  static WallLossLaw linear(double a_db, double b_db_per_ghz);
  static WallLossLaw measured_with_absorption(double anchor_db, double anchor_mhz,
                                              const P2040Material& material, double thickness_m);
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

}  // namespace wifislam::radio_model
