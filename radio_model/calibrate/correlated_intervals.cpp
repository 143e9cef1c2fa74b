#include "radio_model/calibrate/correlated_intervals.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace wifislam::radio_model::calibrate {

void widen_for_correlated_shadowing(PropagationFit& fit, const SurveyLinks& links,
                                    const ShadowingStatistics& shadowing) {
  const Eigen::MatrixXd& a = fit.design;
  const Eigen::Index p = a.cols();
  if (p == 0 || shadowing.decorrelation_m <= 0.0) return;
  const double total_var = shadowing.mean_residual_sigma_db * shadowing.mean_residual_sigma_db;
  const double shared_var = shadowing.shadowing_sigma_db * shadowing.shadowing_sigma_db;

  // A^T S A, one AP at a time (S is block diagonal by AP).
  Eigen::MatrixXd meat = Eigen::MatrixXd::Zero(p, p);
  std::vector<std::vector<Eigen::Index>> rows_of_ap(links.aps.size());
  for (std::size_t r = 0; r < links.groups.size(); ++r)
    rows_of_ap[links.groups[r].ap_index].push_back(static_cast<Eigen::Index>(r));
  for (const auto& rows : rows_of_ap) {
    const auto n = static_cast<Eigen::Index>(rows.size());
    if (n == 0) continue;
    Eigen::MatrixXd b(n, p);
    for (Eigen::Index i = 0; i < n; ++i) b.row(i) = a.row(rows[i]);
    // Row by row (S_i B), so memory stays linear in the AP's positions.
    Eigen::VectorXd s_row(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Vector2d pi = links.groups[rows[i]].position_m.head<2>();
      for (Eigen::Index j = 0; j < n; ++j) {
        const double d = (pi - links.groups[rows[j]].position_m.head<2>()).norm();
        s_row(j) = i == j ? total_var : shared_var * std::exp(-d / shadowing.decorrelation_m);
      }
      meat.noalias() += b.row(i).transpose() * (s_row.transpose() * b);
    }
  }
  const Eigen::MatrixXd bread = (a.transpose() * a).ldlt().solve(Eigen::MatrixXd::Identity(p, p));
  const Eigen::MatrixXd covariance = bread * meat * bread;
  auto ci = [&](int c) { return kZ95 * std::sqrt(std::max(covariance(c, c), 0.0)); };

  fit.distance_coefficient_ci95 = ci(fit.distance_column);
  for (std::size_t i = 0; i < fit.intercept_column.size(); ++i)
    if (fit.intercept_column[i] >= 0) fit.intercept_ci95_db[i] = ci(fit.intercept_column[i]);
  for (int m = 0; m < radio_model::kWallMaterialCount; ++m)
    if (fit.material_column[m] >= 0) fit.materials[m].ci95_db = ci(fit.material_column[m]);
  for (std::size_t d = 0; d < fit.device_column.size(); ++d)
    if (fit.device_column[d] >= 0) fit.device_offset_ci95_db[d] = ci(fit.device_column[d]);
  fit.correlated_intervals = true;
}

}  // namespace wifislam::radio_model::calibrate
