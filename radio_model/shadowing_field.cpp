#include "radio_model/shadowing_field.hpp"

#include <algorithm>
#include <cmath>

namespace wifislam {

ShadowingField::ShadowingField(const Eigen::Vector2d& min_m, const Eigen::Vector2d& max_m,
                               double sigma_db, double decorrelation_m, Rng rng)
    : sigma_db_(sigma_db) {
  if (sigma_db <= 0.0) {
    sigma_db_ = 0.0;
    return;
  }
  const double L = std::max(decorrelation_m, 1e-3);
  cell_m_ = std::min(0.5, L / 4.0);
  const double margin = 2.0;
  origin_m_ = min_m - Eigen::Vector2d(margin, margin);
  const Eigen::Vector2d extent =
      (max_m - min_m).cwiseMax(0.0) + Eigen::Vector2d(2 * margin, 2 * margin);
  cols_ = static_cast<int>(std::ceil(extent.x() / cell_m_)) + 1;
  rows_ = static_cast<int>(std::ceil(extent.y() / cell_m_)) + 1;
  values_.resize(static_cast<std::size_t>(cols_) * rows_);

  const double rho = std::exp(-cell_m_ / L);
  const double innovation = std::sqrt(1.0 - rho * rho);
  std::vector<double> grid(values_.size());
  for (double& v : grid) v = rng.normal();
  for (int r = 0; r < rows_; ++r) {
    double* row = &grid[static_cast<std::size_t>(r) * cols_];
    for (int c = 1; c < cols_; ++c) row[c] = rho * row[c - 1] + innovation * row[c];
  }
  for (int r = 1; r < rows_; ++r) {
    double* row = &grid[static_cast<std::size_t>(r) * cols_];
    const double* prev = row - cols_;
    for (int c = 0; c < cols_; ++c) row[c] = rho * prev[c] + innovation * row[c];
  }
  std::transform(grid.begin(), grid.end(), values_.begin(),
                 [](double v) { return static_cast<float>(v); });
}

double ShadowingField::at_db(const Eigen::Vector2d& p_m) const {
  if (values_.empty()) return 0.0;
  const double gx = std::clamp((p_m.x() - origin_m_.x()) / cell_m_, 0.0, cols_ - 1.0);
  const double gy = std::clamp((p_m.y() - origin_m_.y()) / cell_m_, 0.0, rows_ - 1.0);
  const int c0 = std::min(static_cast<int>(gx), cols_ - 2 < 0 ? 0 : cols_ - 2);
  const int r0 = std::min(static_cast<int>(gy), rows_ - 2 < 0 ? 0 : rows_ - 2);
  const int c1 = std::min(c0 + 1, cols_ - 1), r1 = std::min(r0 + 1, rows_ - 1);
  const double fx = gx - c0, fy = gy - r0;
  auto v = [&](int c, int r) {
    return static_cast<double>(values_[static_cast<std::size_t>(r) * cols_ + c]);
  };
  const double top = v(c0, r0) * (1 - fx) + v(c1, r0) * fx;
  const double bottom = v(c0, r1) * (1 - fx) + v(c1, r1) * fx;
  return sigma_db_ * (top * (1 - fy) + bottom * fy);
}

}  // namespace wifislam
