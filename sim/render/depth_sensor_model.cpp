#include "sim/render/depth_sensor_model.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

#include <fmt/core.h>
#include <opencv2/core/hal/intrin.hpp>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "sim/render/normal_deviates.hpp"

namespace wifislam::sim::render {

#if defined(__x86_64__) && defined(__GNUC__)
namespace {

/// The per-pixel parameters of sense(), with the parts that are off turned into no-ops.
struct SenseParameters {
  float min_range, max_range, cos_grazing, edge_keep, noise_coeff, fb_per_step;
  bool quantise;
};

// sense()'s vector loop eight pixels at a time with 256-bit registers, on CPUs that have AVX2
// (the build targets plain x86-64, so OpenCV's universal intrinsics stop at 128 bits; with two
// divisions a pixel this loop is most of the sensor model's time). The same float operations in
// the same order as the portable loop (a blend or masked AND is v_select; no FMA, which would
// round differently), so every output value is bit-identical. Starts at pixel x and returns the
// first pixel left to do.
__attribute__((target("avx2"))) int sense_row_avx2(const SenseParameters& p, const float* z_row,
                                                   const float* z_up, const float* z_down,
                                                   const float* cos_row, const float* normals,
                                                   int x, int cols, float* out_row) {
  const __m256 zero = _mm256_setzero_ps(), min_range = _mm256_set1_ps(p.min_range),
               max_range = _mm256_set1_ps(p.max_range), cos_grazing = _mm256_set1_ps(p.cos_grazing),
               edge_keep = _mm256_set1_ps(p.edge_keep), noise_coeff = _mm256_set1_ps(p.noise_coeff),
               fb_per_step = _mm256_set1_ps(p.fb_per_step);
  for (; x + 8 < cols; x += 8) {
    const __m256 z = _mm256_loadu_ps(z_row + x);
    const __m256 left = _mm256_loadu_ps(z_row + x - 1), right = _mm256_loadu_ps(z_row + x + 1),
                 up = _mm256_loadu_ps(z_up + x), down = _mm256_loadu_ps(z_down + x);
    const __m256 nearest = _mm256_min_ps(
        _mm256_min_ps(_mm256_blendv_ps(z, left, _mm256_cmp_ps(left, zero, _CMP_GT_OQ)),
                      _mm256_blendv_ps(z, right, _mm256_cmp_ps(right, zero, _CMP_GT_OQ))),
        _mm256_min_ps(_mm256_blendv_ps(z, up, _mm256_cmp_ps(up, zero, _CMP_GT_OQ)),
                      _mm256_blendv_ps(z, down, _mm256_cmp_ps(down, zero, _CMP_GT_OQ))));
    const __m256 keep = _mm256_and_ps(
        _mm256_and_ps(_mm256_cmp_ps(z, zero, _CMP_GT_OQ),
                      _mm256_cmp_ps(_mm256_loadu_ps(cos_row + x), cos_grazing, _CMP_GE_OQ)),
        _mm256_cmp_ps(nearest, _mm256_mul_ps(z, edge_keep), _CMP_GE_OQ));
    __m256 measured =
        _mm256_add_ps(z, _mm256_mul_ps(_mm256_mul_ps(_mm256_mul_ps(noise_coeff, z), z),
                                       _mm256_loadu_ps(normals + x)));
    if (p.quantise) {
      const __m256 steps =
          _mm256_cvtepi32_ps(_mm256_cvtps_epi32(_mm256_div_ps(fb_per_step, measured)));
      measured =
          _mm256_and_ps(_mm256_cmp_ps(steps, zero, _CMP_GT_OQ), _mm256_div_ps(fb_per_step, steps));
    }
    const __m256 valid =
        _mm256_and_ps(_mm256_and_ps(keep, _mm256_cmp_ps(measured, min_range, _CMP_GE_OQ)),
                      _mm256_cmp_ps(measured, max_range, _CMP_LE_OQ));
    _mm256_storeu_ps(out_row + x, _mm256_and_ps(valid, measured));
  }
  return x;
}

}  // namespace
#endif

DepthSensorModel::DepthSensorModel(const scene::DepthSensorSpec& spec,
                                   const CameraIntrinsics& intrinsics, std::uint64_t seed)
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
  if (spec.lateral_noise) {
    lateral_.emplace(spec.lateral_noise_base_px, spec.lateral_noise_angle_coeff_px,
                     spec.grazing_dropout_deg * std::numbers::pi / 180.0, seed);
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
  if (!lateral_) {
    sense(ideal_depth_m, incidence_cos, frame_index, out);
    return;
  }
  // The shift comes first: the sensor sees the shifted scene, so the edge dropouts follow the
  // ragged edges and the axial noise lands on the depth read.
  cv::Mat shifted_depth_m, shifted_cos;
  lateral_->apply(ideal_depth_m, incidence_cos, frame_index, shifted_depth_m, shifted_cos);
  sense(shifted_depth_m, shifted_cos, frame_index, out);
}

void DepthSensorModel::sense(const cv::Mat& ideal_depth_m, const cv::Mat& incidence_cos,
                             std::int64_t frame_index, cv::Mat& out) const {
  CV_Assert(ideal_depth_m.type() == CV_32FC1 && incidence_cos.type() == CV_32FC1 &&
            ideal_depth_m.size() == incidence_cos.size());
  const int rows = ideal_depth_m.rows, cols = ideal_depth_m.cols;
  out.create(rows, cols, CV_32FC1);
  const Rng frame_rng = Rng::stream(seed_, fmt::format("depth_noise/frame{}", frame_index));
  // Every part of the model is written as a select over whole rows, with the parts that are
  // switched off turned into no-ops by their parameters, so the loop vectorises (OpenCV's
  // universal intrinsics) and a frame costs ~1 ms. The scalar tail does the same float
  // operations in the same order, so the result does not depend on the SIMD width.
  const float min_range = static_cast<float>(spec_.min_range_m);
  const float max_range = static_cast<float>(spec_.max_range_m);
  // Dropouts off: no pixel is below cos -1 or nearer than z * (-inf).
  const float cos_grazing = spec_.dropouts ? cos_grazing_ : -1.0f;
  const float edge_keep = spec_.dropouts ? static_cast<float>(1.0 - spec_.edge_jump_fraction)
                                         : -std::numeric_limits<float>::infinity();
  const float noise_coeff = spec_.noise ? static_cast<float>(spec_.axial_noise_coeff_per_m) : 0.0f;
  const bool quantise = spec_.quantisation;
  // Disparity in steps is (f b / step) / z; single precision keeps the steps exact up to ~1e6.
  const float fb_per_step = static_cast<float>(focal_baseline_px_m_ / spec_.disparity_step_px);
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool has_avx2 = __builtin_cpu_supports("avx2");
  const SenseParameters parameters{min_range,   max_range,   cos_grazing, edge_keep,
                                   noise_coeff, fb_per_step, quantise};
#endif

  auto measure_pixel = [&](float z, float left, float right, float up, float down, float cos,
                           float normal) {
    auto surface_or_self = [z](float v) { return v > 0.0f ? v : z; };
    const float nearest = std::min(std::min(surface_or_self(left), surface_or_self(right)),
                                   std::min(surface_or_self(up), surface_or_self(down)));
    const bool keep = z > 0.0f && cos >= cos_grazing && nearest >= z * edge_keep;
    float measured = z + noise_coeff * z * z * normal;
    if (quantise) {
      const float steps = static_cast<float>(cvRound(fb_per_step / measured));
      measured = steps > 0.0f ? fb_per_step / steps : 0.0f;
    }
    return keep && measured >= min_range && measured <= max_range ? measured : 0.0f;
  };

  // Fixed bands of rows, each with its own random sub-stream (one deviate per pixel), so bands
  // could run in parallel with the same result. They run in sequence: at ~1 ms a frame, waking
  // a thread pool costs more than it saves, and its spinning workers slow llvmpipe's next frame.
  constexpr int kBands = 16;
  {
    std::vector<float> normals(static_cast<std::size_t>(cols));
    for (int band = 0; band < kBands; ++band) {
      Rng rng = frame_rng.child(fmt::format("band{}", band));
      for (int y = rows * band / kBands; y < rows * (band + 1) / kBands; ++y) {
        const float* z_row = ideal_depth_m.ptr<float>(y);
        const float* z_up = ideal_depth_m.ptr<float>(y > 0 ? y - 1 : y);
        const float* z_down = ideal_depth_m.ptr<float>(y + 1 < rows ? y + 1 : y);
        const float* cos_row = incidence_cos.ptr<float>(y);
        float* out_row = out.ptr<float>(y);
        fill_normals(rng, normals.data(), cols);
        auto scalar = [&](int x) {
          const float z = z_row[x];
          out_row[x] =
              measure_pixel(z, x > 0 ? z_row[x - 1] : z, x + 1 < cols ? z_row[x + 1] : z, z_up[x],
                            z_down[x], cos_row[x], normals[static_cast<std::size_t>(x)]);
        };
        scalar(0);
        int x = 1;
#if defined(__x86_64__) && defined(__GNUC__)
        if (has_avx2) {
          x = sense_row_avx2(parameters, z_row, z_up, z_down, cos_row, normals.data(), x, cols,
                             out_row);
        }
#endif
#if CV_SIMD128
        using namespace cv;
        const v_float32x4 zero = v_setzero_f32(), v_min_range = v_setall_f32(min_range),
                          v_max_range = v_setall_f32(max_range),
                          v_cos_grazing = v_setall_f32(cos_grazing),
                          v_edge_keep = v_setall_f32(edge_keep),
                          v_noise_coeff = v_setall_f32(noise_coeff),
                          v_fb_per_step = v_setall_f32(fb_per_step);
        for (; x + 4 < cols; x += 4) {
          const v_float32x4 z = v_load(z_row + x);
          auto surface_or_self = [&](const v_float32x4& v) { return v_select(v > zero, v, z); };
          const v_float32x4 nearest = v_min(
              v_min(surface_or_self(v_load(z_row + x - 1)), surface_or_self(v_load(z_row + x + 1))),
              v_min(surface_or_self(v_load(z_up + x)), surface_or_self(v_load(z_down + x))));
          const v_float32x4 keep =
              (z > zero) & (v_load(cos_row + x) >= v_cos_grazing) & (nearest >= z * v_edge_keep);
          v_float32x4 measured = z + v_noise_coeff * z * z * v_load(normals.data() + x);
          if (quantise) {
            const v_float32x4 steps = v_cvt_f32(v_round(v_fb_per_step / measured));
            measured = v_select(steps > zero, v_fb_per_step / steps, zero);
          }
          const v_float32x4 valid = keep & (measured >= v_min_range) & (measured <= v_max_range);
          v_store(out_row + x, v_select(valid, measured, zero));
        }
#endif
        for (; x < cols; ++x) scalar(x);
      }
    }
  }
}

cv::Mat DepthSensorModel::measure(const RenderedView& view, std::int64_t frame_index) const {
  cv::Mat out;
  measure(view.depth_m, view.incidence_cos, frame_index, out);
  return out;
}

}  // namespace wifislam::sim::render
