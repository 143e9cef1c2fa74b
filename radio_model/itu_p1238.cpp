#include "radio_model/itu_p1238.hpp"

#include <algorithm>
#include <cmath>

namespace wifislam::radio_model {

ItuP1238Coefficients itu_p1238_coefficients(RadioEnvironment environment, RadioBand band) {
  // ITU-R P.1238-7, Table 2 (N) and Table 4 (shadow fading sigma, dB).
  //   N        residential  office  commercial
  //   1.8-2 GHz      28        30        22
  //   2.4 GHz        28        30         -
  //   5.2 GHz     28 (house) / 30 (apartment)   31   -
  //   sigma 1.8-2 GHz: 8 / 10 / 10;  5.2 GHz: - / 12 / -
  // Where the table has no entry (commercial at 2.4 and 5.2 GHz, residential sigma at 5.2 GHz)
  // the 1.8-2 GHz value is used. Residential at 5.2 GHz takes the apartment value 30.
  switch (environment) {
    case RadioEnvironment::kResidential:
      return band == RadioBand::k2_4GHz ? ItuP1238Coefficients{28.0, 8.0}
                                        : ItuP1238Coefficients{30.0, 8.0};
    case RadioEnvironment::kOffice:
      return band == RadioBand::k2_4GHz ? ItuP1238Coefficients{30.0, 10.0}
                                        : ItuP1238Coefficients{31.0, 12.0};
    case RadioEnvironment::kCommercial:
      return ItuP1238Coefficients{22.0, 10.0};
  }
  return {};
}

double itu_p1238_floor_loss_db(RadioEnvironment environment, double frequency_mhz, int floors) {
  // ITU-R P.1238-7, Table 3 (the header says which row and why). No floor in between: no loss.
  if (floors <= 0) return 0.0;
  const double further = floors - 1.0;
  const double step_db = environment == RadioEnvironment::kCommercial ? 3.0 : 4.0;
  if (frequency_mhz >= 2200.0 && environment != RadioEnvironment::kCommercial) {
    const bool five_ghz = frequency_mhz >= 4000.0;
    const double one_floor_db = environment == RadioEnvironment::kResidential
                                    ? (five_ghz ? 13.0 : 10.0)
                                    : (five_ghz ? 16.0 : 14.0);
    return one_floor_db + step_db * further;
  }
  switch (environment) {  // 1.8-2 GHz row
    case RadioEnvironment::kResidential:
      return 4.0 * floors;
    case RadioEnvironment::kOffice:
      return 15.0 + 4.0 * further;
    case RadioEnvironment::kCommercial:
      return 6.0 + 3.0 * further;
  }
  return 0.0;
}

ItuSiteGeneralFit itu_p1238_office_fit(bool line_of_sight) {
  // ITU-R P.1238-11, Table 2 (office rows).
  return line_of_sight ? ItuSiteGeneralFit{1.46, 34.62, 2.03, 3.76, 2.0}
                       : ItuSiteGeneralFit{2.46, 29.53, 2.38, 5.04, 4.0};
}

double itu_p1238_fit_loss_db(const ItuSiteGeneralFit& fit, double frequency_mhz,
                             double distance_m) {
  const double d = std::max(distance_m, fit.min_distance_m);
  return 10.0 * fit.alpha * std::log10(d) + fit.beta_db +
         10.0 * fit.gamma * std::log10(frequency_mhz * 1e-3);
}

double itu_p1238_path_loss_db(double frequency_mhz, double distance_m, double distance_coefficient,
                              double floor_loss_db) {
  const double d = std::max(distance_m, 1.0);
  return 20.0 * std::log10(frequency_mhz) + distance_coefficient * std::log10(d) + floor_loss_db -
         28.0;
}

}  // namespace wifislam::radio_model
