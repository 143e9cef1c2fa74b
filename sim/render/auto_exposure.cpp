#include "sim/render/auto_exposure.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "core/error.hpp"

namespace wifislam::sim::render {

AutoExposure::AutoExposure(double target_dn, double time_constant_s, double frame_interval_s,
                           double min_gain, double max_gain)
    : target_dn_(target_dn),
      step_fraction_(1.0 - std::exp(-frame_interval_s / time_constant_s)),
      min_gain_(min_gain),
      max_gain_(max_gain),
      gain_(1.0) {
  if (!(target_dn > 0.0 && target_dn < 255.0)) {
    throw InvalidInputError(fmt::format(
        "sensors.color.exposure_target_dn must be within (0, 255) (got {})", target_dn));
  }
  if (!(time_constant_s > 0.0 && frame_interval_s > 0.0)) {
    throw InvalidInputError(fmt::format(
        "sensors.color: auto-exposure needs exposure_time_constant_s > 0 and a frame interval "
        "> 0 (got {} s and {} s)",
        time_constant_s, frame_interval_s));
  }
  if (!(min_gain > 0.0 && min_gain <= max_gain)) {
    throw InvalidInputError(fmt::format(
        "sensors.color.exposure_gain_range must be [min, max] with 0 < min <= max (got [{}, {}])",
        min_gain, max_gain));
  }
  gain_ = std::clamp(gain_, min_gain, max_gain);  // only now is the range known to be valid
}

void AutoExposure::update(double metered_mean_dn) {
  const double log_gain = std::log(gain_);
  const double wanted = metered_mean_dn > 0.0 ? log_gain + std::log(target_dn_ / metered_mean_dn)
                                              : std::log(max_gain_);
  const double next = log_gain + step_fraction_ * (wanted - log_gain);
  gain_ = std::clamp(std::exp(next), min_gain_, max_gain_);
}

}  // namespace wifislam::sim::render
