#pragma once
// The colour camera's sensor applied to the renderer's ideal colour image (CV_8UC3). Both parts
// are off by default (ColorSensorSpec, scene.hpp; scenes/README.md says why), and with both off
// the output is the rendered image, byte for byte.
//
//  - auto-exposure: a global gain g on the rendered intensities (sim/render/auto_exposure.hpp),
//    the rendered image standing for the scene at gain 1; the rendered 8-bit values are treated
//    as linear in exposure (they are display-encoded, so this is an approximation);
//  - noise: per pixel and channel, independent and Gaussian with variance
//      var (DN^2) = K I + sigma_read^2,   I = g x rendered value (DN),
//    the photon-transfer model of EMVA Standard 1288 (the Poissonian-Gaussian model of A. Foi
//    et al., "Practical Poissonian-Gaussian noise modeling and fitting for single-image raw-data",
//    IEEE TIP 17(10), 2008): shot noise of K = `conversion_gain_dn_per_e` DN per electron and
//    read noise of `read_noise_dn`. The defaults (K = 0.05 DN/e-, i.e. a 5100 e- full well at
//    255 DN, and 0.5 DN = 10 e- read noise) are an assumption typical of small-pixel (2-3 um)
//    webcam sensors, not a measurement of the Kinect's: at the exposure target (118 DN)
//    they give 2.5 DN rms. Demosaicing would correlate neighbouring pixels and channels; this
//    model does not.
//  The result is rounded to the nearest DN and clipped to [0, 255] (rounding adds 1/12 DN^2).
//
// Random draws: Rng::stream(seed, "color_noise/frame<N>"), one child stream per fixed band of
// rows, one deviate per channel value, used or not. Auto-exposure meters each output frame (its
// mean over pixels and channels) to set the next frame's gain, so with it on the model has state
// and must see frames 0, 1, 2, ... in order; the noise of a frame depends only on the seed, the
// frame index and the gain.

#include <cstdint>
#include <optional>

#include <opencv2/core.hpp>

#include "sim/render/auto_exposure.hpp"
#include "sim/scene/scene.hpp"

namespace wifislam::sim::render {

class ColorSensorModel {
 public:
  /// `fps`: the camera's frame rate (auto-exposure's time step). Throws InvalidInputError for
  /// bad parameters (negative noise, an empty gain range, ...).
  ColorSensorModel(const scene::ColorSensorSpec& spec, double fps, std::uint64_t seed);

  /// The sensor's image of frame `frame_index` from the rendered one (CV_8UC3). With
  /// auto-exposure on, frames must come in order from 0 (std::logic_error otherwise). `out` may
  /// not alias `rendered_bgr`.
  void measure(const cv::Mat& rendered_bgr, std::int64_t frame_index, cv::Mat& out);

  /// Noise variance (DN^2) at exposed intensity I (DN), before rounding and clipping.
  double noise_variance_dn2(double intensity_dn) const;
  /// The gain the next frame gets (1 without auto-exposure).
  double gain() const { return auto_exposure_ ? auto_exposure_->gain() : 1.0; }
  const scene::ColorSensorSpec& spec() const { return spec_; }

 private:
  scene::ColorSensorSpec spec_;
  std::uint64_t seed_;
  std::optional<AutoExposure> auto_exposure_;
  std::int64_t next_frame_ = 0;
};

}  // namespace wifislam::sim::render
