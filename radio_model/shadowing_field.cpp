#include "radio_model/shadowing_field.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/core.hpp>

namespace wifislam::radio_model {

namespace {

// The torus is this many decorrelation distances wider than the site: the wrap-around
// covariance between two nodes of the site is then at most exp(-10) = 4.5e-5.
constexpr double kTorusPaddingDecorrelations = 10.0;

}  // namespace

ShadowingGrid::ShadowingGrid(const Eigen::Vector2d& min_m, const Eigen::Vector2d& max_m,
                             double sigma_db, double decorrelation_m)
    : sigma_db_(std::max(sigma_db, 0.0)), decorrelation_m_(std::max(decorrelation_m, 1e-3)) {
  if (sigma_db_ == 0.0) return;
  const double L = decorrelation_m_;
  const double margin = 2.0;
  origin_m_ = min_m - Eigen::Vector2d(margin, margin);
  const Eigen::Vector2d extent =
      (max_m - min_m).cwiseMax(0.0) + Eigen::Vector2d(2 * margin, 2 * margin);
  // Cells of a twelfth of the decorrelation distance (at most 0.25 m), coarser when that would
  // exceed kMaxCells (sites over about 125 m across; see the header).
  cell_m_ = std::min(0.25, L / 12.0);
  const double cells_at_fine = (extent.x() / cell_m_ + 2) * (extent.y() / cell_m_ + 2);
  if (cells_at_fine > static_cast<double>(kMaxCells)) {
    cell_m_ *= std::sqrt(cells_at_fine / static_cast<double>(kMaxCells)) * 1.01;
  }
  cols_ = static_cast<int>(std::ceil(extent.x() / cell_m_)) + 1;
  rows_ = static_cast<int>(std::ceil(extent.y() / cell_m_)) + 1;

  const int padding = static_cast<int>(std::ceil(kTorusPaddingDecorrelations * L / cell_m_));
  torus_cols_ = cv::getOptimalDFTSize(cols_ + padding);
  torus_rows_ = cv::getOptimalDFTSize(rows_ + padding);
  // First row of the block-circulant covariance: C at wrap-around distances from node (0, 0).
  cv::Mat covariance(torus_rows_, torus_cols_, CV_64F);
  for (int r = 0; r < torus_rows_; ++r) {
    const double dy = std::min(r, torus_rows_ - r) * cell_m_;
    auto* row = covariance.ptr<double>(r);
    for (int c = 0; c < torus_cols_; ++c) {
      const double dx = std::min(c, torus_cols_ - c) * cell_m_;
      row[c] = std::exp(-std::hypot(dx, dy) / L);
    }
  }
  // The covariance is real and even, so its DFT (the eigenvalues) is real: take the real part
  // of the full complex output (a real input's default output is OpenCV's packed CCS layout).
  cv::Mat eigenvalues;
  cv::dft(covariance, eigenvalues, cv::DFT_COMPLEX_OUTPUT);
  const double cells = static_cast<double>(torus_cols_) * torus_rows_;
  sqrt_eigenvalues_.resize(static_cast<std::size_t>(torus_cols_) * torus_rows_);
  double total = 0.0, negative = 0.0;
  for (int r = 0; r < torus_rows_; ++r) {
    const auto* row = eigenvalues.ptr<cv::Vec2d>(r);
    for (int c = 0; c < torus_cols_; ++c) {
      const double lambda = row[c][0];
      total += std::abs(lambda);
      if (lambda < 0.0) negative -= lambda;
      sqrt_eigenvalues_[static_cast<std::size_t>(r) * torus_cols_ + c] =
          std::sqrt(std::max(lambda, 0.0) / cells);
    }
  }
  negative_mass_ = total > 0.0 ? negative / total : 0.0;
}

ShadowingGrid::~ShadowingGrid() = default;
ShadowingGrid::ShadowingGrid(ShadowingGrid&&) noexcept = default;
ShadowingGrid& ShadowingGrid::operator=(ShadowingGrid&&) noexcept = default;

ShadowingField ShadowingGrid::draw(Rng rng) const {
  ShadowingField field;
  if (sigma_db_ == 0.0) return field;
  field.sigma_db_ = sigma_db_;
  field.cell_m_ = cell_m_;
  field.rho_axis_ = std::exp(-cell_m_ / decorrelation_m_);
  field.rho_diagonal_ = std::exp(-std::sqrt(2.0) * cell_m_ / decorrelation_m_);
  field.origin_m_ = origin_m_;
  field.cols_ = cols_;
  field.rows_ = rows_;

  // sqrt(lambda / cells) * (a + ib), a and b independent N(0, 1): the real part of its DFT has
  // covariance C on the torus (and the imaginary part is an independent copy, unused so that
  // each AP's field draws from its own stream only).
  cv::Mat spectrum(torus_rows_, torus_cols_, CV_64FC2);
  for (int r = 0; r < torus_rows_; ++r) {
    auto* row = spectrum.ptr<cv::Vec2d>(r);
    const double* scale = &sqrt_eigenvalues_[static_cast<std::size_t>(r) * torus_cols_];
    for (int c = 0; c < torus_cols_; ++c) {
      const double re = rng.normal(), im = rng.normal();
      row[c] = cv::Vec2d(scale[c] * re, scale[c] * im);
    }
  }
  cv::Mat values;
  cv::dft(spectrum, values);
  field.values_.resize(static_cast<std::size_t>(cols_) * rows_);
  for (int r = 0; r < rows_; ++r) {
    const auto* row = values.ptr<cv::Vec2d>(r);
    for (int c = 0; c < cols_; ++c)
      field.values_[static_cast<std::size_t>(r) * cols_ + c] = static_cast<float>(row[c][0]);
  }
  return field;
}

ShadowingField::ShadowingField(const Eigen::Vector2d& min_m, const Eigen::Vector2d& max_m,
                               double sigma_db, double decorrelation_m, Rng rng)
    : ShadowingField(ShadowingGrid(min_m, max_m, sigma_db, decorrelation_m).draw(std::move(rng))) {}

double ShadowingField::at_db(const Eigen::Vector2d& p_m) const {
  if (values_.empty()) return 0.0;
  const double gx = std::clamp((p_m.x() - origin_m_.x()) / cell_m_, 0.0, cols_ - 1.0);
  const double gy = std::clamp((p_m.y() - origin_m_.y()) / cell_m_, 0.0, rows_ - 1.0);
  const int c0 = std::min(static_cast<int>(gx), std::max(cols_ - 2, 0));
  const int r0 = std::min(static_cast<int>(gy), std::max(rows_ - 2, 0));
  const int c1 = std::min(c0 + 1, cols_ - 1), r1 = std::min(r0 + 1, rows_ - 1);
  const double fx = gx - c0, fy = gy - r0;
  auto v = [&](int c, int r) {
    return static_cast<double>(values_[static_cast<std::size_t>(r) * cols_ + c]);
  };
  const double w00 = (1 - fx) * (1 - fy), w10 = fx * (1 - fy), w01 = (1 - fx) * fy, w11 = fx * fy;
  const double blend = w00 * v(c0, r0) + w10 * v(c1, r0) + w01 * v(c0, r1) + w11 * v(c1, r1);
  // Variance of the blend of four unit-variance corners correlated as C (see the header).
  const double variance = w00 * w00 + w10 * w10 + w01 * w01 + w11 * w11 +
                          2 * rho_axis_ * (w00 * w10 + w01 * w11 + w00 * w01 + w10 * w11) +
                          2 * rho_diagonal_ * (w00 * w11 + w10 * w01);
  return sigma_db_ * blend / std::sqrt(variance);
}

}  // namespace wifislam::radio_model
