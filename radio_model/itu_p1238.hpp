#pragma once
// Indoor path loss of Recommendation ITU-R P.1238 (site-general model of sections 3.1 / Tables 2-4
// in P.1238-7 to -9), the formula ns-3's ItuR1238PropagationLossModel implements:
//
//   L(d) = 20 log10(f_MHz) + N log10(d_m) + Lf(n) - 28   [dB]
//
// N: distance power loss coefficient, Lf(n): floor penetration loss for n floors between the
// terminals, both from the recommendation's tables for the environment and band. The shadow
// fading standard deviation comes from the same recommendation (Table 4).

#include "radio_model/path_loss_choice.hpp"
#include "radio_model/radio_band.hpp"

namespace wifislam::radio_model {

struct ItuP1238Coefficients {
  double distance_coefficient = 30.0;  // N
  double shadow_sigma_db = 10.0;       // log-normal shadow fading standard deviation
};

/// N and sigma from the recommendation's tables for an environment and band.
ItuP1238Coefficients itu_p1238_coefficients(RadioEnvironment environment, RadioBand band);

/// Lf(n) for n floors between transmitter and receiver at `frequency_mhz` (0 on the same storey),
/// from ITU-R P.1238-7 Table 3 (floor penetration loss factors, dB):
///                residential               office                 commercial
///   1.8-2 GHz    4 n                       15 + 4 (n - 1)         6 + 3 (n - 1)
///   2.4 GHz      10 (apartment), 5 (house) 14                     -
///   5.2 GHz      13 (apartment), 7 (house) 16 (1 floor)           -
/// Rows by band: below 2.2 GHz the 1.8-2 GHz row, below 4 GHz the 2.4 GHz row, above it the
/// 5.2 GHz row (as N uses it for all of 5 GHz). Choices where the table is silent, as for N:
/// residential takes the apartment value (P.1238's residential rows are for multi-storey
/// dwellings, the buildings with floors to cross); commercial, which has no 2.4 or 5.2 GHz entry,
/// keeps the 1.8-2 GHz row; and for more than one floor at 2.4 or 5.2 GHz, where the table gives
/// one value, each further floor adds the 1.8-2 GHz row's step (4 dB; 3 dB commercial).
double itu_p1238_floor_loss_db(RadioEnvironment environment, double frequency_mhz, int floors);

/// L(d) in dB. Distances below 1 m are taken as 1 m: the model is stated for d > 1 m and the
/// log term would otherwise turn into a gain.
double itu_p1238_path_loss_db(double frequency_mhz, double distance_m, double distance_coefficient,
                              double floor_loss_db);

/// The site-general fit of ITU-R P.1238-11 (2021), section 3.1, equation (1) and Table 2:
///   L(d, f) = 10 alpha log10(d_m) + beta + 10 gamma log10(f_GHz)   [dB],  sigma: its spread.
/// Office rows (the ones our environments have): line of sight 1.46 / 34.62 / 2.03, sigma 3.76 dB,
/// fitted over 2-27 m; non line of sight 2.46 / 29.53 / 2.38, sigma 5.04 dB, over 4-30 m (both
/// 0.3-83.5 GHz). The table also has corridor and factory rows, which are path types rather than
/// building types and are not used.
struct ItuSiteGeneralFit {
  double alpha = 0.0, beta_db = 0.0, gamma = 0.0, sigma_db = 0.0;
  double min_distance_m = 1.0;  // shortest distance of the fit's data
};
ItuSiteGeneralFit itu_p1238_office_fit(bool line_of_sight);

/// L(d, f) of a fit row. Distances below the row's shortest are taken as the shortest: the fit
/// is not stated there, and with the clamp the NLoS loss exceeds the LoS loss at every distance
/// in the Wi-Fi bands (2.4-5.9 GHz), so a wall can only lower RSSI.
double itu_p1238_fit_loss_db(const ItuSiteGeneralFit& fit, double frequency_mhz, double distance_m);

/// The distance coefficient used when the scene does not set `radio.distance_coefficient`.
/// P.1238's office N = 30 (31 at 5.2 GHz) lumps the walls of a typical office into the distance
/// term; we ray-cast every wall and add its loss explicitly, so keeping N = 30 would count the
/// walls twice. We therefore use N = 22, the recommendation's own coefficient for commercial
/// (open-plan, few walls) buildings at 1.8-2 GHz: the distance law of indoor space without
/// partitions, with furniture and people. With it the formula is the COST 231 multi-wall model
/// (free-space-like distance term plus per-wall losses) slightly steepened; the ITU
/// site-general corridor fits of P.1238-10 (LoS a = 1.63, NLoS a = 2.77, i.e. N = 16.3 .. 27.7)
/// bracket it.
inline constexpr double kDefaultDistanceCoefficient = 22.0;

}  // namespace wifislam::radio_model
