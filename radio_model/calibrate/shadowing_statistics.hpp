#pragma once
// The random parts of the model, from the residuals of a fit (propagation_fit.hpp), kept apart:
//
//  - fast fading: the scatter of samples around their own position's mean, pooled over every
//    position and AP (sqrt of sum of squared deviations / sum of (n - 1));
//  - shadowing sigma: the spread of the position means around the fitted model, less what the
//    fast fading still adds to a mean of n samples: sigma_s^2 = s_mean^2 - mean(s_ff^2 / n);
//  - shadowing decorrelation distance L: the empirical correlation of two positions' mean
//    residuals of the same AP, binned by their horizontal separation (0.5 m bins up to 15 m),
//    fitted by rho(d) = rho0 exp(-d / L) (Gudmundson, the simulator's covariance,
//    shadowing_field.hpp), rho0 = sigma_s^2 / s_mean^2 the share of the means' variance that is
//    shadowing; L is the grid value in [0.5, 100] m (1 % steps) with the least pair-weighted
//    squared error. Its uncertainty is not estimated (pairs are far from independent).

#include <vector>

#include "radio_model/calibrate/propagation_fit.hpp"
#include "radio_model/calibrate/survey_links.hpp"

namespace wifislam::radio_model::calibrate {

struct CorrelationBin {
  double separation_m = 0.0;  // bin centre
  long long pairs = 0;
  double correlation = 0.0;
};

struct ShadowingStatistics {
  double fast_fading_sigma_db = 0.0;
  double shadowing_sigma_db = 0.0;
  double mean_residual_sigma_db = 0.0;  // s_mean
  double decorrelation_m = 0.0;
  std::vector<CorrelationBin> correlation;
};

ShadowingStatistics shadowing_statistics(const SurveyLinks& links, const LinearRadioModel& model,
                                         int fitted_parameters);

}  // namespace wifislam::radio_model::calibrate
