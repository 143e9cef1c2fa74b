#include "sim/render/lateral_depth_noise.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <fmt/core.h>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "sim/render/normal_deviates.hpp"

namespace wifislam::sim::render {

namespace {

/// Mean square of round(scale x q) over the deviate table (ties at k + 1/2 aside, which have
/// probability zero): sum over k >= 1 of (2k - 1) P(|scale q| >= k - 1/2). The table is sorted.
double rounded_variance(double scale) {
  const auto& table = normal_quantiles();
  if (scale <= 0.0) return 0.0;
  double sum = 0.0;
  for (int k = 1;; ++k) {
    const float threshold = static_cast<float>((k - 0.5) / scale);
    const auto above = table.end() - std::lower_bound(table.begin(), table.end(), threshold);
    if (above == 0) break;
    sum += (2.0 * k - 1.0) * 2.0 * static_cast<double>(above);  // both tails (symmetric table)
  }
  return sum / static_cast<double>(table.size());
}

}  // namespace

LateralDepthNoise::LateralDepthNoise(double base_px, double angle_coeff_px, double max_theta_rad,
                                     std::uint64_t seed)
    : base_px_(base_px),
      angle_coeff_px_(angle_coeff_px),
      max_theta_rad_(max_theta_rad),
      seed_(seed) {
  if (!(base_px >= 0.0 && angle_coeff_px >= 0.0)) {
    throw InvalidInputError(
        fmt::format("sensors.depth: lateral noise needs lateral_noise_base_px >= 0 and "
                    "lateral_noise_angle_coeff_px >= 0 (got {} and {})",
                    base_px, angle_coeff_px));
  }
  if (!(max_theta_rad >= 0.0 && max_theta_rad < std::numbers::pi / 2)) {
    throw InvalidInputError(
        fmt::format("sensors.depth: lateral noise needs grazing_dropout_deg below 90 (got {} deg)",
                    max_theta_rad * 180.0 / std::numbers::pi));
  }
  const auto& table = normal_quantiles();
  for (int code = 0; code < 256; ++code) {
    const double target_var = std::pow(stddev_px(std::acos(code / 255.0)), 2);
    // rounded_variance grows with the scale; bisect between 0 and a scale that overshoots.
    double lo = 0.0, hi = 1.0;
    while (rounded_variance(hi) < target_var) hi *= 2.0;
    for (int i = 0; i < 40; ++i) {
      const double mid = 0.5 * (lo + hi);
      (rounded_variance(mid) < target_var ? lo : hi) = mid;
    }
    scale_[code] = static_cast<float>(hi);
    // What apply() does with it, exactly.
    double sum_sq = 0.0;
    for (const float q : table) sum_sq += std::pow(cvRound(scale_[code] * q), 2);
    shift_stddev_px_[code] = std::sqrt(sum_sq / static_cast<double>(table.size()));
  }
}

double LateralDepthNoise::stddev_px(double theta_rad) const {
  const double theta = std::clamp(theta_rad, 0.0, max_theta_rad_);
  return base_px_ + angle_coeff_px_ * theta / (std::numbers::pi / 2 - theta);
}

double LateralDepthNoise::shift_stddev_px(int incidence_code) const {
  return shift_stddev_px_.at(static_cast<std::size_t>(incidence_code));
}

void LateralDepthNoise::apply(const cv::Mat& depth_m, const cv::Mat& incidence_cos,
                              std::int64_t frame_index, cv::Mat& depth_out,
                              cv::Mat& cos_out) const {
  CV_Assert(depth_m.type() == CV_32FC1 && incidence_cos.type() == CV_32FC1 &&
            depth_m.size() == incidence_cos.size());
  const int rows = depth_m.rows, cols = depth_m.cols;
  depth_out.create(rows, cols, CV_32FC1);
  cos_out.create(rows, cols, CV_32FC1);
  CV_Assert(depth_out.data != depth_m.data && cos_out.data != incidence_cos.data);
  const Rng frame_rng = Rng::stream(seed_, fmt::format("depth_lateral/frame{}", frame_index));
  // Fixed bands, each with its own sub-stream, as in DepthSensorModel: the same shifts whatever
  // the thread count, should the bands ever run in parallel.
  constexpr int kBands = 16;
  std::vector<float> normals(2 * static_cast<std::size_t>(cols));
  for (int band = 0; band < kBands; ++band) {
    Rng rng = frame_rng.child(fmt::format("band{}", band));
    for (int y = rows * band / kBands; y < rows * (band + 1) / kBands; ++y) {
      fill_normals(rng, normals.data(), 2 * cols);
      const float* cos_row = incidence_cos.ptr<float>(y);
      float* depth_row_out = depth_out.ptr<float>(y);
      float* cos_row_out = cos_out.ptr<float>(y);
      for (int x = 0; x < cols; ++x) {
        const int code = std::clamp(cvRound(cos_row[x] * 255.0f), 0, 255);
        const float scale = scale_[static_cast<std::size_t>(code)];
        const int sx =
            std::clamp(x + cvRound(scale * normals[static_cast<std::size_t>(x)]), 0, cols - 1);
        const int sy = std::clamp(y + cvRound(scale * normals[static_cast<std::size_t>(cols + x)]),
                                  0, rows - 1);
        depth_row_out[x] = depth_m.ptr<float>(sy)[sx];
        cos_row_out[x] = incidence_cos.ptr<float>(sy)[sx];
      }
    }
  }
}

}  // namespace wifislam::sim::render
