#include "sim/render/color_sensor_model.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <fmt/core.h>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "sim/render/normal_deviates.hpp"

namespace wifislam::sim::render {

ColorSensorModel::ColorSensorModel(const scene::ColorSensorSpec& spec, double fps,
                                   std::uint64_t seed)
    : spec_(spec), seed_(seed) {
  if (spec.noise && !(spec.conversion_gain_dn_per_e >= 0.0 && spec.read_noise_dn >= 0.0)) {
    throw InvalidInputError(fmt::format(
        "sensors.color: noise needs conversion_gain_dn_per_e >= 0 and read_noise_dn >= 0 (got {} "
        "and {})",
        spec.conversion_gain_dn_per_e, spec.read_noise_dn));
  }
  if (spec.auto_exposure) {
    if (!(fps > 0.0)) {
      throw InvalidInputError(
          fmt::format("sensors.camera.fps must be > 0 for auto-exposure (got {})", fps));
    }
    auto_exposure_.emplace(spec.exposure_target_dn, spec.exposure_time_constant_s, 1.0 / fps,
                           spec.exposure_min_gain, spec.exposure_max_gain);
  }
}

double ColorSensorModel::noise_variance_dn2(double intensity_dn) const {
  return spec_.conversion_gain_dn_per_e * intensity_dn + spec_.read_noise_dn * spec_.read_noise_dn;
}

void ColorSensorModel::measure(const cv::Mat& rendered_bgr, std::int64_t frame_index,
                               cv::Mat& out) {
  CV_Assert(rendered_bgr.type() == CV_8UC3);
  if (!spec_.noise && !auto_exposure_) {
    rendered_bgr.copyTo(out);
    return;
  }
  if (auto_exposure_ && frame_index != next_frame_) {
    throw std::logic_error(fmt::format(
        "ColorSensorModel: auto-exposure needs frames in order; got frame {}, expected {}",
        frame_index, next_frame_));
  }
  const int rows = rendered_bgr.rows, values_per_row = rendered_bgr.cols * 3;
  out.create(rendered_bgr.size(), CV_8UC3);
  CV_Assert(out.data != rendered_bgr.data);
  // Both parts depend on the rendered value only through 256 numbers: tabulate them per frame.
  const float gain_now = static_cast<float>(gain());
  std::array<float, 256> exposed_dn{}, noise_sd_dn{};
  for (int v = 0; v < 256; ++v) {
    exposed_dn[static_cast<std::size_t>(v)] = gain_now * static_cast<float>(v);
    noise_sd_dn[static_cast<std::size_t>(v)] =
        spec_.noise
            ? static_cast<float>(std::sqrt(noise_variance_dn2(gain_now * static_cast<float>(v))))
            : 0.0f;
  }
  if (!spec_.noise) {
    cv::Mat lut(1, 256, CV_8U);
    for (int v = 0; v < 256; ++v)
      lut.at<std::uint8_t>(v) =
          cv::saturate_cast<std::uint8_t>(exposed_dn[static_cast<std::size_t>(v)]);
    cv::LUT(rendered_bgr, lut, out);
  } else {
    const Rng frame_rng = Rng::stream(seed_, fmt::format("color_noise/frame{}", frame_index));
    // Fixed bands with their own sub-streams, as in DepthSensorModel.
    constexpr int kBands = 16;
    std::vector<float> normals(static_cast<std::size_t>(values_per_row));
    for (int band = 0; band < kBands; ++band) {
      Rng rng = frame_rng.child(fmt::format("band{}", band));
      for (int y = rows * band / kBands; y < rows * (band + 1) / kBands; ++y) {
        fill_normals(rng, normals.data(), values_per_row);
        const std::uint8_t* in = rendered_bgr.ptr<std::uint8_t>(y);
        std::uint8_t* o = out.ptr<std::uint8_t>(y);
        for (int i = 0; i < values_per_row; ++i) {
          const std::size_t v = in[i];
          o[i] = cv::saturate_cast<std::uint8_t>(
              exposed_dn[v] + noise_sd_dn[v] * normals[static_cast<std::size_t>(i)]);
        }
      }
    }
  }
  if (auto_exposure_) {
    // The camera meters what it took (clipped, noisy); integer sums, so exact.
    const cv::Scalar sums = cv::sum(out);
    const double mean_dn = (sums[0] + sums[1] + sums[2]) / (3.0 * static_cast<double>(out.total()));
    auto_exposure_->update(mean_dn);
    ++next_frame_;
  }
}

}  // namespace wifislam::sim::render
