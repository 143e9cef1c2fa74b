#pragma once
// Auto-exposure of the colour camera: one global gain, applied to a whole frame, that moves the
// frame's metered mean brightness toward a target. A first-order loop in log gain:
//
//   log g_{k+1} = log g_k + a (log T - log m_k),   a = 1 - exp(-dt / tau),
//
// with m_k the mean (DN) of frame k as taken with gain g_k, T the target, dt the frame interval
// and tau the time constant. On a still scene (m_k = g_k x m) the log error log T - log m_k
// shrinks by exp(-dt / tau) a frame, i.e. as exp(-t / tau). The gain starts at 1 (the rendered
// image as it is) and stays within [min_gain, max_gain]; frame k's gain comes from frames before
// it only, as a real camera meters the last frame to set the next one's exposure.
//
// Its state is the gain, so a frame's image depends on the frames before it: the model must see
// frames in order (GenerationPipeline produces them in order), and the same sequence always gives
// the same gains. No randomness.

namespace wifislam::sim::render {

class AutoExposure {
 public:
  /// Throws InvalidInputError unless 0 < target_dn < 255, time_constant_s > 0,
  /// frame_interval_s > 0 and 0 < min_gain <= max_gain.
  AutoExposure(double target_dn, double time_constant_s, double frame_interval_s, double min_gain,
               double max_gain);

  /// The gain for the next frame.
  double gain() const { return gain_; }
  /// Share of the log error removed per frame: 1 - exp(-dt / tau).
  double step_fraction() const { return step_fraction_; }
  double target_dn() const { return target_dn_; }

  /// After a frame taken with gain() metered `mean_dn` (its mean over pixels and channels):
  /// sets the next frame's gain. A black frame (mean 0) moves toward the largest gain.
  void update(double metered_mean_dn);

 private:
  double target_dn_, step_fraction_, min_gain_, max_gain_;
  double gain_;
};

}  // namespace wifislam::sim::render
