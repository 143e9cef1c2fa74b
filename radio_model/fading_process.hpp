#pragma once
// Fast fading of one radio (one access point's 2.4 GHz or 5 GHz transmitter) as a stationary
// Gaussian process in dB over time and receiver position, so that
//  - every BSSID of the radio sees the same fading (they share its channel and antenna);
//  - scans at a still receiver are correlated over a coherence time tau:
//      corr(dt) = exp(-|dt| / tau);
//    Youssef & Agrawala ("Handling samples correlation in the Horus system", INFOCOM 2004)
//    measured the autocorrelation of consecutive 1-s RSSI samples of one AP at up to 0.9;
//  - moving decorrelates it as Clarke's isotropic scattering does:
//      corr(d) = J0(2 pi d / lambda),
//    within a few centimetres (half a wavelength is 6 cm at 2.4 GHz), so scans taken on the
//    move are independent.
//
// Construction: a sum of K random plane waves (sum-of-sinusoids, as Jakes' and Clarke's
// simulators are built),
//   g(t, p) = sqrt(2 / K) sum_k cos(omega_k t + (2 pi / lambda) u(theta_k) . p + phi_k),
// theta_k and phi_k uniform on [0, 2 pi), omega_k Cauchy-distributed with scale 1 / tau (whose
// characteristic function is exactly exp(-|dt| / tau)). Over radios (the ensemble) g has zero
// mean, unit variance and the product of the two correlations above; one radio's realisation
// matches them to about 1 / sqrt(K). It is stateless: the value at (t, p) needs no history, so a
// scan never depends on which scans came before it.

#include <vector>

#include <Eigen/Core>

#include "core/rng.hpp"

namespace wifislam::radio_model {

class FadingProcess {
 public:
  static constexpr int kPlaneWaves = 64;
  static_assert((kPlaneWaves & (kPlaneWaves - 1)) == 0, "max_abs_db needs an exact scaling");

  /// A zero process (no fading).
  FadingProcess() = default;
  /// sigma_db: standard deviation; coherence_s: tau (> 0); frequency_mhz: the radio's carrier.
  /// `rng` is consumed (3 draws per plane wave).
  FadingProcess(double sigma_db, double coherence_s, double frequency_mhz, Rng rng);

  /// Fading in dB at time `time_s` and receiver position `position_m` (x, y on the floor).
  double at_db(double time_s, const Eigen::Vector2d& position_m) const;
  /// A bound on |at_db(...)| that holds for the computed values, not only in exact arithmetic:
  /// each cosine is within [-1, 1], so every partial sum of K of them rounds to within [-K, K],
  /// and scaling by a power of two (K = 64) is exact. The scanner uses it to skip the sum where
  /// no fading could lift a BSSID above the receiver's sensitivity.
  double max_abs_db() const { return amplitude_db_ * kPlaneWaves; }

 private:
  struct PlaneWave {
    double angular_frequency_rad_s;
    Eigen::Vector2d wave_vector_rad_m;
    double phase_rad;
  };
  double amplitude_db_ = 0.0;  // sigma * sqrt(2 / K)
  std::vector<PlaneWave> waves_;
};

}  // namespace wifislam::radio_model
