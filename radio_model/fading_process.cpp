#include "radio_model/fading_process.hpp"

#include <cmath>
#include <numbers>

namespace wifislam::radio_model {

namespace {
constexpr double kSpeedOfLightMps = 299'792'458.0;
}  // namespace

FadingProcess::FadingProcess(double sigma_db, double coherence_s, double frequency_mhz, Rng rng) {
  if (sigma_db <= 0.0) return;
  amplitude_db_ = sigma_db * std::sqrt(2.0 / kPlaneWaves);
  const double wavenumber_rad_m = 2.0 * std::numbers::pi * frequency_mhz * 1e6 / kSpeedOfLightMps;
  waves_.reserve(kPlaneWaves);
  for (int k = 0; k < kPlaneWaves; ++k) {
    // Cauchy(0, 1 / tau) by inversion; u in (0, 1) keeps tan finite.
    const double u = rng.uniform(1e-12, 1.0 - 1e-12);
    const double omega = std::tan(std::numbers::pi * (u - 0.5)) / coherence_s;
    const double theta = rng.uniform(0.0, 2.0 * std::numbers::pi);
    const double phase = rng.uniform(0.0, 2.0 * std::numbers::pi);
    waves_.push_back(
        {omega, wavenumber_rad_m * Eigen::Vector2d(std::cos(theta), std::sin(theta)), phase});
  }
}

double FadingProcess::at_db(double time_s, const Eigen::Vector2d& position_m) const {
  double sum = 0.0;
  for (const PlaneWave& w : waves_) {
    sum += std::cos(w.angular_frequency_rad_s * time_s + w.wave_vector_rad_m.dot(position_m) +
                    w.phase_rad);
  }
  return amplitude_db_ * sum;
}

}  // namespace wifislam::radio_model
