#include "radio_model/wall_materials.hpp"

#include <cmath>
#include <complex>
#include <numbers>

namespace wifislam::radio_model {

namespace {
constexpr double kSpeedOfLightMps = 299'792'458.0;
constexpr double kPlasterboardSheetM = 0.0125;  // one 12.5 mm board of a stud partition
}  // namespace

double p2040_slab_loss_db(const P2040Material& m, double thickness_m, double frequency_mhz) {
  using C = std::complex<double>;
  const double f_ghz = frequency_mhz * 1e-3;
  const double eta_real = m.a * std::pow(f_ghz, m.b);
  const double sigma_spm = m.c * std::pow(f_ghz, m.d);
  const C eta(eta_real, -17.98 * sigma_spm / f_ghz);
  const C n = std::sqrt(eta);  // principal root: loss as a negative imaginary part
  const C r = (1.0 - n) / (1.0 + n);
  const C q = 2.0 * std::numbers::pi * frequency_mhz * 1e6 * thickness_m / kSpeedOfLightMps * n;
  const C j(0.0, 1.0);
  const C t = (1.0 - r * r) * std::exp(-j * q) / (1.0 - r * r * std::exp(-2.0 * j * q));
  return -20.0 * std::log10(std::abs(t));
}

double p2040_absorption_db(const P2040Material& m, double thickness_m, double frequency_mhz) {
  const double f_ghz = frequency_mhz * 1e-3;
  const std::complex<double> eta(m.a * std::pow(f_ghz, m.b),
                                 -17.98 * m.c * std::pow(f_ghz, m.d) / f_ghz);
  const double k0 = 2.0 * std::numbers::pi * frequency_mhz * 1e6 / kSpeedOfLightMps;
  return 20.0 * std::log10(std::exp(1.0)) * k0 * std::abs(std::sqrt(eta).imag()) * thickness_m;
}

double WallLossLaw::at(double frequency_mhz) const {
  if (anchored) {
    return anchor_db + p2040_absorption_db(material, thickness_m, frequency_mhz) -
           p2040_absorption_db(material, thickness_m, anchor_mhz);
  }
  return a_db + b_db_per_ghz * frequency_mhz * 1e-3;
}

WallLossLaw WallLossLaw::linear(double a_db, double b_db_per_ghz) {
  WallLossLaw law;
  law.a_db = a_db;
  law.b_db_per_ghz = b_db_per_ghz;
  return law;
}

WallLossLaw WallLossLaw::measured_with_absorption(double anchor_db, double anchor_mhz,
                                                  const P2040Material& material,
                                                  double thickness_m) {
  WallLossLaw law;
  law.anchored = true;
  law.anchor_db = anchor_db;
  law.anchor_mhz = anchor_mhz;
  law.material = material;
  law.thickness_m = thickness_m;
  return law;
}

WallLossTable::WallLossTable(double wall_thickness_m) {
  // TR 38.901 Table 7.4.3-1: concrete, standard glass, wood.
  laws[material_index(WallMaterial::kConcrete)] = WallLossLaw::linear(5.0, 4.0);
  laws[material_index(WallMaterial::kGlass)] = WallLossLaw::linear(2.0, 0.2);
  laws[material_index(WallMaterial::kWoodDoor)] = WallLossLaw::linear(4.85, 0.12);
  // COST 231 at 1800 MHz, with the frequency dependence of the material's absorption (P.2040-3):
  // masonry of the wall's thickness (heavy wall); a stud partition of two boards (light wall).
  laws[material_index(WallMaterial::kBrick)] =
      WallLossLaw::measured_with_absorption(6.9, 1800.0, kP2040Brick, wall_thickness_m);
  laws[material_index(WallMaterial::kPlasterboard)] = WallLossLaw::measured_with_absorption(
      3.4, 1800.0, kP2040Plasterboard, 2.0 * kPlasterboardSheetM);
}

}  // namespace wifislam::radio_model
