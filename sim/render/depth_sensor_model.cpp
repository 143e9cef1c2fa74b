#include "sim/render/depth_sensor_model.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include <fmt/core.h>
#include <boost/math/special_functions/erf.hpp>
#include <opencv2/core/utility.hpp>

#include "core/error.hpp"
#include "core/rng.hpp"

namespace wifislam {

namespace {

// Standard normal quantiles at 2^16 evenly spaced probabilities: one 64-bit draw gives four
// normal deviates through a table lookup. Rng::normal() costs ~10x more, and a 640x480 frame
// needs ~300k deviates inside a few-millisecond frame budget. The table truncates the tails at
// +-4.2 sigma, which changes the variance by < 0.1 %.
const std::array<float, 65536>& normal_quantiles() {
  static const std::array<float, 65536> table = [] {
    std::array<float, 65536> t{};
    for (std::size_t i = 0; i < t.size(); ++i) {
      const double p = (static_cast<double>(i) + 0.5) / static_cast<double>(t.size());
      t[i] = static_cast<float>(-std::numbers::sqrt2 * boost::math::erfc_inv(2.0 * p));
    }
    return t;
  }();
  return table;
}

class FastNormal {
 public:
  explicit FastNormal(Rng rng) : rng_(rng), table_(normal_quantiles()) {}
  float next() {
    if (left_ == 0) {
      bits_ = rng_.next_u64();
      left_ = 4;
    }
    const float value = table_[bits_ & 0xffffu];
    bits_ >>= 16;
    --left_;
    return value;
  }

 private:
  Rng rng_;
  const std::array<float, 65536>& table_;
  std::uint64_t bits_ = 0;
  int left_ = 0;
};

}  // namespace

DepthSensorModel::DepthSensorModel(const DepthSensorSpec& spec, const CameraIntrinsics& intrinsics,
                                   std::uint64_t seed)
    : spec_(spec),
      focal_baseline_px_m_(intrinsics.fx_px * spec.baseline_m),
      cos_grazing_(
          static_cast<float>(std::cos(spec.grazing_dropout_deg * std::numbers::pi / 180.0))),
      seed_(seed) {
  if (!(spec.min_range_m >= 0.0 && spec.min_range_m < spec.max_range_m)) {
    throw InvalidInputError(
        fmt::format("sensors.depth: need 0 <= min_range_m < max_range_m (got {} and {})",
                    spec.min_range_m, spec.max_range_m));
  }
  if (spec.quantisation && !(spec.baseline_m > 0.0 && spec.disparity_step_px > 0.0)) {
    throw InvalidInputError(
        fmt::format("sensors.depth: quantisation needs baseline_m > 0 and disparity_step_px > 0 "
                    "(got {} and {})",
                    spec.baseline_m, spec.disparity_step_px));
  }
  if (spec.noise && spec.axial_noise_coeff_per_m < 0.0) {
    throw InvalidInputError(
        fmt::format("sensors.depth.axial_noise_coeff_per_m must be >= 0 (got {})",
                    spec.axial_noise_coeff_per_m));
  }
}

double DepthSensorModel::axial_noise_stddev_m(double z_m) const {
  return spec_.axial_noise_coeff_per_m * z_m * z_m;
}

double DepthSensorModel::quantised_depth_m(double z_m) const {
  const double disparity_px = focal_baseline_px_m_ / z_m;
  const double steps = std::nearbyint(disparity_px / spec_.disparity_step_px);
  if (steps <= 0.0) return 0.0;  // beyond the farthest representable disparity
  return focal_baseline_px_m_ / (steps * spec_.disparity_step_px);
}

void DepthSensorModel::measure(const cv::Mat& ideal_depth_m, const cv::Mat& incidence_cos,
                               std::int64_t frame_index, cv::Mat& out) const {
  CV_Assert(ideal_depth_m.type() == CV_32FC1 && incidence_cos.type() == CV_32FC1 &&
            ideal_depth_m.size() == incidence_cos.size());
  const int rows = ideal_depth_m.rows, cols = ideal_depth_m.cols;
  out.create(rows, cols, CV_32FC1);
  const Rng frame_rng = Rng::stream(seed_, fmt::format("depth_noise/frame{}", frame_index));
  const float min_range = static_cast<float>(spec_.min_range_m);
  const float max_range = static_cast<float>(spec_.max_range_m);
  const float edge_keep = static_cast<float>(1.0 - spec_.edge_jump_fraction);
  const float noise_coeff = static_cast<float>(spec_.axial_noise_coeff_per_m);
  // Disparity in steps is (f b / step) / z; single precision keeps the steps exact up to ~1e6.
  const float fb_per_step = static_cast<float>(focal_baseline_px_m_ / spec_.disparity_step_px);

  // Fixed bands of rows, each with its own random sub-stream: the result does not depend on how
  // many threads run the bands.
  constexpr int kBands = 16;
  cv::parallel_for_(cv::Range(0, kBands), [&](const cv::Range& bands) {
    for (int band = bands.start; band < bands.end; ++band) {
      FastNormal normal(frame_rng.child(fmt::format("band{}", band)));
      for (int y = rows * band / kBands; y < rows * (band + 1) / kBands; ++y) {
        const float* z_row = ideal_depth_m.ptr<float>(y);
        const float* z_up = ideal_depth_m.ptr<float>(y > 0 ? y - 1 : y);
        const float* z_down = ideal_depth_m.ptr<float>(y + 1 < rows ? y + 1 : y);
        const float* cos_row = incidence_cos.ptr<float>(y);
        float* out_row = out.ptr<float>(y);
        for (int x = 0; x < cols; ++x) {
          float z = z_row[x];
          if (z <= 0.0f) {
            out_row[x] = 0.0f;
            continue;
          }
          if (spec_.dropouts) {
            // Far side of an edge: a neighbour with a surface is nearer than z * (1 - jump).
            auto surface_or_self = [z](float v) { return v > 0.0f ? v : z; };
            const float nearest =
                std::min(std::min(surface_or_self(x > 0 ? z_row[x - 1] : z),
                                  surface_or_self(x + 1 < cols ? z_row[x + 1] : z)),
                         std::min(surface_or_self(z_up[x]), surface_or_self(z_down[x])));
            if (cos_row[x] < cos_grazing_ || nearest < z * edge_keep) {
              out_row[x] = 0.0f;
              continue;
            }
          }
          if (spec_.noise) z += noise_coeff * z * z * normal.next();
          if (spec_.quantisation && z > 0.0f) {
            const float steps = std::nearbyint(fb_per_step / z);
            z = steps > 0.0f ? fb_per_step / steps : 0.0f;
          }
          out_row[x] = (z >= min_range && z <= max_range) ? z : 0.0f;
        }
      }
    }
  });
}

cv::Mat DepthSensorModel::measure(const RenderedView& view, std::int64_t frame_index) const {
  cv::Mat out;
  measure(view.depth_m, view.incidence_cos, frame_index, out);
  return out;
}

}  // namespace wifislam
