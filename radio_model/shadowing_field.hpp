#pragma once
// Spatially correlated log-normal shadowing of one access point: a zero-mean Gaussian field in
// dB over the floor plan whose correlation between two points a distance apart along x or y
// falls as exp(-distance / decorrelation), Gudmundson's model ("Correlation model for shadow
// fading in mobile radio systems", Electronics Letters 27(23), 1991). Two scans at the same
// spot therefore see the same shadowing; spots a few decorrelation distances apart are
// independent.
//
// Construction: white Gaussian noise on a grid (cell h <= decorrelation / 4) filtered by a
// first-order autoregressive filter along rows and then along columns,
//   y[i] = rho y[i-1] + sqrt(1 - rho^2) w[i],  rho = exp(-h / decorrelation),  y[0] = w[0],
// which is stationary with unit variance and gives exactly the separable covariance
// exp(-|dx| / L) exp(-|dy| / L) on the grid nodes (Gudmundson's exponential along every
// axis-aligned path, such as a corridor). Values between nodes are bilinear. This is O(cells),
// exact on the grid and cheap to evaluate, unlike a sum of random cosines which needs hundreds of
// cosines per evaluation for the same fidelity.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/rng.hpp"

namespace wifislam {

class ShadowingField {
 public:
  /// A zero field (no shadowing).
  ShadowingField() = default;
  /// Field over the rectangle [min_m, max_m] (plus a margin); points outside take the value of
  /// the nearest edge. `rng` is consumed.
  ShadowingField(const Eigen::Vector2d& min_m, const Eigen::Vector2d& max_m, double sigma_db,
                 double decorrelation_m, Rng rng);

  double at_db(const Eigen::Vector2d& p_m) const;
  double sigma_db() const { return sigma_db_; }
  double cell_m() const { return cell_m_; }

 private:
  double sigma_db_ = 0.0;
  double cell_m_ = 1.0;
  Eigen::Vector2d origin_m_ = Eigen::Vector2d::Zero();
  int cols_ = 0, rows_ = 0;
  std::vector<float> values_;  // row-major, unit variance (scaled by sigma in at_db)
};

}  // namespace wifislam
