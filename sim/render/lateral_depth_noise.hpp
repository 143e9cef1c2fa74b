#pragma once
// Lateral (in-image) noise of a Kinect v1 depth image, after C. V. Nguyen, S. Izadi and D. Lovell,
// "Modeling Kinect Sensor Noise for Improved 3D Reconstruction and Tracking", 3DIMPVT 2012:
//
//   sigma_L(theta) = base + coeff * theta / (pi/2 - theta)   [px; their fit: 0.8 px, 0.035 px]
//
// with theta the angle between the surface normal and the viewing ray. Each pixel reads the
// depth (and incidence) of a pixel shifted by a random whole-pixel offset (dx, dy), drawn
// independently per axis with standard deviation sigma_L at the pixel's own theta.
//
// Why whole pixels (nearest-neighbour sampling, not interpolation): Nguyen et al. measured
// sigma_L as the spread of edge pixels' positions in the depth image, which are whole pixels,
// and a Kinect reading is a depth some surface has: interpolating across a depth edge would
// invent mixed depths between foreground and background. Edges come out ragged by whole pixels,
// as a real Kinect's are. Rounding changes a Gaussian's spread, so the Gaussian is scaled before
// rounding such that the whole-pixel shift has exactly variance sigma_L^2 over the deviate table
// (sim/render/normal_deviates.hpp). theta comes from the renderer's |cos theta| (steps of 1/255),
// so there are 256 scales, computed once. theta is capped at `max_theta_rad` (the grazing
// dropout angle): the fit diverges at 90 deg, Nguyen et al. fitted it below ~80 deg, and beyond
// the cap a Kinect has no reading anyway. Shifts are clamped to the image (edge pixels repeat).
//
// Random draws: Rng::stream(seed, "depth_lateral/frame<N>"), one child stream per fixed band of
// rows, two deviates per pixel (dx for the whole row, then dy), used or not: a frame's shifts
// depend only on the seed and the frame index.

#include <array>
#include <cstdint>

#include <opencv2/core.hpp>

namespace wifislam::sim::render {

class LateralDepthNoise {
 public:
  /// Throws InvalidInputError unless base_px >= 0, angle_coeff_px >= 0 and
  /// 0 <= max_theta_rad < pi/2.
  LateralDepthNoise(double base_px, double angle_coeff_px, double max_theta_rad,
                    std::uint64_t seed);

  /// sigma_L (px) at incidence angle theta (rad), theta capped at max_theta_rad.
  double stddev_px(double theta_rad) const;
  /// Standard deviation of the whole-pixel shift applied at renderer incidence code
  /// round(|cos theta| x 255) (what the scaling achieves; equals stddev_px up to ~1e-3 px).
  double shift_stddev_px(int incidence_code) const;

  /// `depth_out` and `cos_out` (CV_32FC1) read the inputs at each pixel's shifted position.
  /// The outputs may not alias the inputs.
  void apply(const cv::Mat& depth_m, const cv::Mat& incidence_cos, std::int64_t frame_index,
             cv::Mat& depth_out, cv::Mat& cos_out) const;

 private:
  double base_px_, angle_coeff_px_, max_theta_rad_;
  std::array<float, 256> scale_{};  // per incidence code: multiplies a unit deviate before rounding
  std::array<double, 256> shift_stddev_px_{};
  std::uint64_t seed_;
};

}  // namespace wifislam::sim::render
