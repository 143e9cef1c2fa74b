// The depth sensor model behaves like the Kinect model it cites: noise with the documented
// spread, readings only inside the valid range, disparity steps, dropouts where a structured-light
// sensor has none.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <opencv2/core/utility.hpp>

#include "core/error.hpp"
#include "core/pose.hpp"
#include "sim/render/depth_sensor_model.hpp"
#include "sim/render/rgbd_renderer.hpp"
#include "tests/render/test_meshes.hpp"

namespace wifislam {
namespace {

DepthSensorSpec only(bool noise, bool quantisation, bool dropouts) {
  DepthSensorSpec spec;
  spec.noise = noise;
  spec.quantisation = quantisation;
  spec.dropouts = dropouts;
  return spec;
}

RenderedView wall_view(RgbdRenderer& renderer, double distance_m) {
  renderer.set_world(test::wall_facing_minus_x(distance_m), {}, 1, AppearanceThemes{});
  return renderer.render(camera_pose_from_planar(0.0, 0.0, 0.0, 0.0));
}

TEST(DepthSensorModel, AxialNoiseAtThreeMetresMatchesKhoshelhamElberink) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  RgbdRenderer renderer(k);
  const RenderedView view = wall_view(renderer, 3.0);
  const DepthSensorModel model(only(true, false, true), k, 42);
  // Per-pixel spread over many frames, pooled over a central patch.
  constexpr int kFrames = 60;
  const cv::Rect patch(220, 140, 200, 200);
  cv::Mat sum(patch.size(), CV_64F, cv::Scalar(0)), sum_sq(patch.size(), CV_64F, cv::Scalar(0));
  for (int f = 0; f < kFrames; ++f) {
    cv::Mat z;
    model.measure(view, f)(patch).convertTo(z, CV_64F);
    ASSERT_EQ(cv::countNonZero(z <= 0.0), 0);
    sum += z;
    sum_sq += z.mul(z);
  }
  const cv::Mat mean = sum / kFrames;
  const cv::Mat variance = (sum_sq - kFrames * mean.mul(mean)) / (kFrames - 1);
  const double empirical_std_m = std::sqrt(cv::mean(variance)[0]);
  const double model_std_m = model.axial_noise_stddev_m(3.0);
  EXPECT_NEAR(model_std_m, 1.425e-3 * 9.0, 1e-12);
  EXPECT_NEAR(empirical_std_m, model_std_m, 0.10 * model_std_m)
      << "empirical " << empirical_std_m << " model " << model_std_m;
  EXPECT_NEAR(cv::mean(mean)[0], 3.0, 1e-3);  // unbiased
}

TEST(DepthSensorModel, NothingOutsideTheValidRangeSurvives) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  RgbdRenderer renderer(k);
  const DepthSensorModel model(DepthSensorSpec{}, k, 7);
  // Near the far limit, noise pushes about half the readings past 4 m: they must be dropped.
  const cv::Mat far = model.measure(wall_view(renderer, 3.98), 0);
  double lo = 0, hi = 0;
  cv::minMaxLoc(far, &lo, &hi, nullptr, nullptr, far > 0.0f);
  EXPECT_GE(lo, 0.8);
  EXPECT_LE(hi, 4.0);
  const int valid = cv::countNonZero(far > 0.0f);
  EXPECT_GT(valid, 1000);
  EXPECT_LT(valid, far.rows * far.cols - 1000);
  // Too close and too far: no reading at all.
  EXPECT_EQ(cv::countNonZero(model.measure(wall_view(renderer, 0.6), 0)), 0);
  EXPECT_EQ(cv::countNonZero(model.measure(wall_view(renderer, 4.5), 0)), 0);
  // Every part off but the range: readings equal the ideal depth.
  const DepthSensorModel ideal(only(false, false, false), k, 7);
  const RenderedView mid = wall_view(renderer, 2.0);
  EXPECT_EQ(cv::norm(ideal.measure(mid, 0), mid.depth_m, cv::NORM_INF), 0.0);
}

TEST(DepthSensorModel, QuantisationPutsReadingsOnTheDisparityGrid) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  RgbdRenderer renderer(k);
  renderer.set_world(test::wall_facing_minus_x(3.0), {}, 1, AppearanceThemes{});
  // Oblique view: a continuum of true depths between ~1.5 m and 4 m.
  const RenderedView view = renderer.render(camera_pose_from_planar(0.0, 0.0, 0.9, 0.0));
  const DepthSensorSpec spec = only(false, true, false);
  const DepthSensorModel model(spec, k, 3);
  const cv::Mat z = model.measure(view, 0);
  const double fb = k.fx_px * spec.baseline_m;
  int checked = 0;
  for (int v = 0; v < z.rows; v += 4) {
    for (int u = 0; u < z.cols; u += 4) {
      const float measured = z.at<float>(v, u);
      if (measured <= 0.0f) continue;
      const double steps = fb / measured / spec.disparity_step_px;
      EXPECT_NEAR(steps, std::round(steps), 1e-3);
      // Rounding the disparity moves depth by at most half a step: dz = z^2 / (f b) * step / 2.
      const double ideal = view.depth_m.at<float>(v, u);
      EXPECT_LE(std::abs(measured - ideal),
                ideal * ideal / fb * spec.disparity_step_px * 0.5 + 1e-5);
      ++checked;
    }
  }
  EXPECT_GT(checked, 5000);
  // The step at 3 m: 3^2 / (525 * 0.075) / 8 = 2.9 cm.
  EXPECT_NEAR(model.quantised_depth_m(3.0) - model.quantised_depth_m(3.03), -0.0286, 0.003);
}

TEST(DepthSensorModel, GrazingAnglesGiveNoReading) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  RgbdRenderer renderer(k);
  // A wall 0.35 m away, looked at almost along it: rays meet it at 44 to 90 deg from its
  // normal, and those beyond 82 deg still hit it within the 4 m range.
  renderer.set_world(test::wall_facing_minus_x(0.35), {}, 1, AppearanceThemes{});
  const RenderedView view = renderer.render(camera_pose_from_planar(0.0, 0.0, 1.3, 0.0));
  const DepthSensorModel model(only(false, false, true), k, 3);
  const cv::Mat z = model.measure(view, 0);
  const double cos_limit = std::cos(82.0 * std::numbers::pi / 180.0);
  int dropped = 0, kept = 0;
  for (int v = 0; v < z.rows; ++v) {
    for (int u = 1; u + 1 < z.cols; ++u) {
      const double c = view.incidence_cos.at<float>(v, u), ideal = view.depth_m.at<float>(v, u);
      if (ideal < 0.8 || ideal > 4.0) continue;
      if (c < cos_limit - 1e-3) {
        EXPECT_EQ(z.at<float>(v, u), 0.0f);
        ++dropped;
      } else if (c > cos_limit + 1e-3) {
        EXPECT_FLOAT_EQ(z.at<float>(v, u), ideal);
        ++kept;
      }
    }
  }
  EXPECT_GT(dropped, 1000);
  EXPECT_GT(kept, 1000);
}

TEST(DepthSensorModel, FarSideOfDepthEdgesIsDropped) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  RgbdRenderer renderer(k);
  const test::HandCorridor corridor = test::hand_corridor();
  renderer.set_world(corridor.mesh, corridor.lights, 1, AppearanceThemes{});
  // Facing the pillar (x 13.0-13.4) from 2.5 m, with the end wall 9.5 m behind it; the range
  // limit is lifted so the far side of the edge would otherwise have a reading.
  const RenderedView view = renderer.render(camera_pose_from_planar(10.5, 0.0, 0.0, 1.0));
  DepthSensorSpec spec = only(false, false, true);
  spec.max_range_m = 30.0;
  const DepthSensorModel model(spec, k, 3);
  const cv::Mat z = model.measure(view, 0);
  int edges = 0;
  for (int v = 0; v < z.rows; ++v) {
    for (int u = 1; u + 1 < z.cols; ++u) {
      const float a = view.depth_m.at<float>(v, u), b = view.depth_m.at<float>(v, u + 1);
      if (a <= 0 || b <= 0 || std::abs(a - b) < 0.2f * std::min(a, b)) continue;
      // The farther of the two pixels has no reading; the nearer one keeps it unless grazing.
      const bool a_far = a > b;
      EXPECT_EQ(z.at<float>(v, a_far ? u : u + 1), 0.0f);
      const int near_u = a_far ? u + 1 : u;
      if (view.incidence_cos.at<float>(v, near_u) > 0.2f) {
        EXPECT_GT(z.at<float>(v, near_u), 0.0f);
      }
      ++edges;
    }
  }
  EXPECT_GT(edges, 200);
}

TEST(DepthSensorModel, SameFrameSameNoiseOtherFrameOtherNoise) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  RgbdRenderer renderer(k);
  const RenderedView view = wall_view(renderer, 2.0);
  const DepthSensorModel model(DepthSensorSpec{}, k, 11);
  EXPECT_EQ(cv::norm(model.measure(view, 4), model.measure(view, 4), cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(model.measure(view, 4), model.measure(view, 5), cv::NORM_INF), 0.0);
  // The same numbers whatever the thread count.
  const cv::Mat parallel = model.measure(view, 4);
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);
  const cv::Mat serial = model.measure(view, 4);
  cv::setNumThreads(threads);
  EXPECT_EQ(cv::norm(parallel, serial, cv::NORM_INF), 0.0);
  const DepthSensorModel other_seed(DepthSensorSpec{}, k, 12);
  EXPECT_GT(cv::norm(model.measure(view, 4), other_seed.measure(view, 4), cv::NORM_INF), 0.0);
}

TEST(DepthSensorModel, RejectsInconsistentParameters) {
  DepthSensorSpec spec;
  spec.min_range_m = 5.0;
  EXPECT_THROW(DepthSensorModel(spec, CameraIntrinsics::kinect_v1(), 1), InvalidInputError);
  spec = DepthSensorSpec{};
  spec.disparity_step_px = 0.0;
  EXPECT_THROW(DepthSensorModel(spec, CameraIntrinsics::kinect_v1(), 1), InvalidInputError);
}

}  // namespace
}  // namespace wifislam
