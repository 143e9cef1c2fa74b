#include "radio_model/calibrate/shadowing_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wifislam::radio_model::calibrate {

namespace {
constexpr double kBinM = 0.5, kMaxSeparationM = 15.0;
constexpr double kMinDecorrelationM = 0.5, kMaxDecorrelationM = 100.0;
}  // namespace

ShadowingStatistics shadowing_statistics(const SurveyLinks& links, const LinearRadioModel& model,
                                         int fitted_parameters) {
  ShadowingStatistics out;
  double within_ss = 0.0, within_dof = 0.0, fading_in_means = 0.0, mean_ss = 0.0;
  std::vector<double> residual(links.groups.size());
  for (std::size_t i = 0; i < links.groups.size(); ++i) {
    const LinkGroup& g = links.groups[i];
    double ss = 0.0;
    for (double r : g.rss_dbm) ss += (r - g.mean_dbm) * (r - g.mean_dbm);
    const double n = static_cast<double>(g.rss_dbm.size());
    within_ss += ss;
    within_dof += n - 1.0;
    if (n > 1.0) fading_in_means += ss / (n - 1.0) / n;
    residual[i] = g.mean_dbm - model.predict_dbm(g);
    mean_ss += residual[i] * residual[i];
  }
  const double groups = static_cast<double>(links.groups.size());
  out.fast_fading_sigma_db = within_dof > 0.0 ? std::sqrt(within_ss / within_dof) : 0.0;
  const double mean_var = mean_ss / std::max(1.0, groups - fitted_parameters);
  out.mean_residual_sigma_db = std::sqrt(mean_var);
  const double shadowing_var = std::max(0.0, mean_var - fading_in_means / std::max(1.0, groups));
  out.shadowing_sigma_db = std::sqrt(shadowing_var);

  // Pairs of positions of the same AP, binned by separation.
  const int bins = static_cast<int>(kMaxSeparationM / kBinM);
  std::vector<double> product(bins, 0.0);
  std::vector<long long> pairs(bins, 0);
  for (std::size_t i = 0; i < links.groups.size(); ++i) {
    for (std::size_t j = i + 1; j < links.groups.size(); ++j) {
      if (links.groups[i].ap_index != links.groups[j].ap_index) continue;
      const double d =
          (links.groups[i].position_m.head<2>() - links.groups[j].position_m.head<2>()).norm();
      const int b = static_cast<int>(d / kBinM);
      if (b >= bins) continue;
      product[b] += residual[i] * residual[j];
      ++pairs[b];
    }
  }
  for (int b = 0; b < bins; ++b) {
    if (pairs[b] == 0) continue;
    out.correlation.push_back({(b + 0.5) * kBinM, pairs[b], product[b] / pairs[b] / mean_var});
  }
  const double rho0 = mean_var > 0.0 ? shadowing_var / mean_var : 0.0;
  double best_error = std::numeric_limits<double>::infinity();
  for (double l = kMinDecorrelationM; l <= kMaxDecorrelationM; l *= 1.01) {
    double error = 0.0;
    for (const CorrelationBin& c : out.correlation) {
      const double e = c.correlation - rho0 * std::exp(-c.separation_m / l);
      error += static_cast<double>(c.pairs) * e * e;
    }
    if (error < best_error) {
      best_error = error;
      out.decorrelation_m = l;
    }
  }
  return out;
}

}  // namespace wifislam::radio_model::calibrate
