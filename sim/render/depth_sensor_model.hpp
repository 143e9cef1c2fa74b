#pragma once
// A Kinect-v1-like depth sensor applied to the renderer's ideal depth. Each part can be switched
// off in DepthSensorSpec (scene.hpp), which also holds the parameters:
//
//  - dropouts: no reading where the viewing ray meets the surface at more than
//    `grazing_dropout_deg` from the normal (structured light returns no pattern there; ICL-NUIM
//    and simkinect use ~82 deg), nor on the far side of depth edges (the projector's shadow): a
//    pixel with a 4-neighbour nearer by more than `edge_jump_fraction` x z has no reading;
//  - axial noise: Gaussian with sigma_z = `axial_noise_coeff_per_m` x z^2, the model fitted by
//    K. Khoshelham and S. O. Elberink, "Accuracy and Resolution of Kinect Depth Data for Indoor
//    Mapping Applications", Sensors 12(2), 2012 (sigma_z = 1.425e-3 z^2 m, z in m);
//  - quantisation: the Kinect measures disparity d = f b / z (f = fx, b = `baseline_m`, 0.075 m)
//    in steps of `disparity_step_px` (1/8 px); depth is recomputed from the rounded disparity, as
//    in ICL-NUIM (Handa et al., ICRA 2014) and simkinect;
//  - valid range: readings outside [min_range_m, max_range_m] are dropped (always on);
//  - lateral noise (off by default): each pixel reads the scene at a random whole-pixel shift
//    with sigma_L = 0.8 + 0.035 theta / (pi/2 - theta) px (Nguyen, Izadi and Lovell 2012), so
//    depth edges are ragged; applied first (sim/render/lateral_depth_noise.hpp).
//
// Random draws come from Rng::stream(seed, "depth_noise/frame<N>") (one child stream per fixed
// band of rows, so bands run in parallel; one deviate per pixel, used or not), so a frame's noise
// depends only on the seed and the frame index, whatever the thread count or SIMD width. The
// lateral shifts have their own stream, so switching them on leaves the axial deviates as they
// were.

#include <cstdint>
#include <optional>

#include <opencv2/core.hpp>

#include "core/camera_intrinsics.hpp"
#include "sim/render/lateral_depth_noise.hpp"
#include "sim/render/rgbd_renderer.hpp"
#include "sim/scene/scene.hpp"

namespace wifislam::sim::render {

class DepthSensorModel {
 public:
  /// Throws InvalidInputError for inconsistent parameters (e.g. min_range_m >= max_range_m).
  DepthSensorModel(const scene::DepthSensorSpec& spec, const CameraIntrinsics& intrinsics,
                   std::uint64_t seed);

  /// Measured depth (CV_32FC1, metres, 0 = no reading) of frame `frame_index` from an ideal
  /// depth image and the matching |cos| incidence image. `out` may not alias the inputs.
  void measure(const cv::Mat& ideal_depth_m, const cv::Mat& incidence_cos, std::int64_t frame_index,
               cv::Mat& out) const;
  cv::Mat measure(const RenderedView& view, std::int64_t frame_index) const;

  /// Standard deviation of the axial noise at depth z (metres), before quantisation.
  double axial_noise_stddev_m(double z_m) const;
  /// The depth on the disparity grid nearest to z (what quantisation returns for z).
  double quantised_depth_m(double z_m) const;

  const scene::DepthSensorSpec& spec() const { return spec_; }
  /// The lateral noise model, when spec().lateral_noise is on.
  const std::optional<LateralDepthNoise>& lateral_noise() const { return lateral_; }

 private:
  /// Everything after the lateral shift: dropouts, axial noise, quantisation, range.
  void sense(const cv::Mat& ideal_depth_m, const cv::Mat& incidence_cos, std::int64_t frame_index,
             cv::Mat& out) const;

  scene::DepthSensorSpec spec_;
  double focal_baseline_px_m_;  // f b
  float cos_grazing_;
  std::uint64_t seed_;
  std::optional<LateralDepthNoise> lateral_;
};

}  // namespace wifislam::sim::render
