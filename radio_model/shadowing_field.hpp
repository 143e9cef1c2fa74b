#pragma once
// Spatially correlated log-normal shadowing of one access point: a zero-mean Gaussian field in
// dB over the floor plan with variance sigma^2 and the isotropic covariance
//   C(d) = sigma^2 exp(-d / decorrelation),  d = Euclidean distance,
// Gudmundson's model ("Correlation model for shadow fading in mobile radio systems",
// Electronics Letters 27(23), 1991) applied in the plane. Two scans at the same spot see the same
// shadowing; spots a few decorrelation distances apart are independent, in every direction.
//
// Construction (circulant embedding, Dietrich & Newsam, SIAM J. Sci. Comput. 18(4), 1997): the
// grid (cell h <= decorrelation / 12) is embedded in a torus at least ten decorrelation distances
// larger than the site, where C is written with wrap-around distances. The torus covariance is
// diagonalised by the 2-D DFT (OpenCV's cv::dft); its eigenvalues lambda are computed once per
// site (ShadowingGrid), and one AP's field is the real part of DFT(sqrt(lambda / cells) * Z)
// for complex white noise Z. On the grid nodes that field has covariance C exactly, up to the
// wrap-around term exp(-10) and any negative eigenvalue clipped to zero (negative_mass() says how
// much; it is below 1e-6 of the total for the exponential covariance at these paddings).
// An earlier separable construction (first-order filters along rows and columns) had the right
// covariance along the axes only: exp(-2) instead of exp(-sqrt(2)) on a diagonal.
//
// Between nodes the value is the bilinear blend of the four corners divided by the blend's
// standard deviation under C, so every point, not just the nodes, has variance sigma^2 (plain
// bilinear blending loses 7 % of the variance mid-cell at h = L / 12, and 3/4 of it once
// nodes are independent). The price: correlations between points off the nodes come out a few
// hundredths above C (measured +0.03 at 0.5-1.5 m for h = L / 12; +0.06 at h = L / 6, which is
// why the cells are this fine). Exact variance was preferred to exact covariance off the nodes
// because the shadowing's spread is what a radio map or a Wi-Fi similarity sees first.
//
// Memory: one float per cell per access point. The grid is capped at kMaxCells (1 MB per AP);
// a site larger than about 125 m x 125 m (every shipped twin is smaller) gets coarser cells,
// and its field then decorrelates over about one cell where that exceeds the requested
// distance (at 20 km across, the scene limit, cells are about 40 m).

#include <cstddef>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "core/rng.hpp"

namespace wifislam::radio_model {

class ShadowingField;

/// The grid and covariance spectrum shared by every access point of a site: built once, it
/// draws one field per AP.
class ShadowingGrid {
 public:
  static constexpr std::size_t kMaxCells = std::size_t{1} << 18;

  /// Grid over the rectangle [min_m, max_m] plus a margin. sigma_db <= 0 gives zero fields.
  ShadowingGrid(const Eigen::Vector2d& min_m, const Eigen::Vector2d& max_m, double sigma_db,
                double decorrelation_m);
  ~ShadowingGrid();
  ShadowingGrid(ShadowingGrid&&) noexcept;
  ShadowingGrid& operator=(ShadowingGrid&&) noexcept;

  /// One field; `rng` is consumed (cells x 2 normal draws).
  ShadowingField draw(Rng rng) const;

  double cell_m() const { return cell_m_; }
  /// Share of the embedding's spectrum that was negative and clipped to zero.
  double negative_mass() const { return negative_mass_; }

 private:
  friend class ShadowingField;
  double sigma_db_ = 0.0;
  double decorrelation_m_ = 1.0;
  double cell_m_ = 1.0;
  Eigen::Vector2d origin_m_ = Eigen::Vector2d::Zero();
  int cols_ = 0, rows_ = 0;               // the site's grid
  int torus_cols_ = 0, torus_rows_ = 0;   // its circulant embedding
  std::vector<double> sqrt_eigenvalues_;  // sqrt(lambda / cells), torus row-major
  double negative_mass_ = 0.0;
};

class ShadowingField {
 public:
  /// Kept for callers that need one field: ShadowingGrid(min_m, max_m, ...).draw(rng).
  static constexpr std::size_t kMaxCells = ShadowingGrid::kMaxCells;

  /// A zero field (no shadowing).
  ShadowingField() = default;
  /// One field over [min_m, max_m]; points outside take the value of the nearest edge.
  ShadowingField(const Eigen::Vector2d& min_m, const Eigen::Vector2d& max_m, double sigma_db,
                 double decorrelation_m, Rng rng);

  double at_db(const Eigen::Vector2d& p_m) const;
  double sigma_db() const { return sigma_db_; }
  double cell_m() const { return cell_m_; }
  std::size_t memory_bytes() const { return values_.size() * sizeof(float); }

 private:
  friend class ShadowingGrid;
  double sigma_db_ = 0.0;
  double cell_m_ = 1.0;
  double rho_axis_ = 0.0;      // correlation of two nodes one cell apart
  double rho_diagonal_ = 0.0;  // ... one cell diagonal apart
  Eigen::Vector2d origin_m_ = Eigen::Vector2d::Zero();
  int cols_ = 0, rows_ = 0;
  std::vector<float> values_;  // row-major, unit variance (scaled by sigma in at_db)
};

}  // namespace wifislam::radio_model
