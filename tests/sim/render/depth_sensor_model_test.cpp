// The depth sensor model behaves like the Kinect model it cites: noise with the documented
// spread, readings only inside the valid range, disparity steps, dropouts where a structured-light
// sensor has none, lateral shifts with Nguyen et al.'s spread, and the default output pinned.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <string_view>

#include <opencv2/core/utility.hpp>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/pose.hpp"
#include "sim/render/depth_sensor_model.hpp"
#include "sim/render/rgbd_renderer.hpp"
#include "tests/sim/render/test_meshes.hpp"

namespace wifislam::sim {
namespace {

scene::DepthSensorSpec only(bool noise, bool quantisation, bool dropouts) {
  scene::DepthSensorSpec spec;
  spec.noise = noise;
  spec.quantisation = quantisation;
  spec.dropouts = dropouts;
  return spec;
}

render::RenderedView wall_view(render::RgbdRenderer& renderer, double distance_m) {
  renderer.set_world(test::wall_facing_minus_x(distance_m), {}, 1, scene::AppearanceThemes{});
  return renderer.render(camera_pose_from_planar(0.0, 0.0, 0.0, 0.0));
}

TEST(DepthSensorModel, AxialNoiseAtThreeMetresMatchesKhoshelhamElberink) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  render::RgbdRenderer renderer(k);
  const render::RenderedView view = wall_view(renderer, 3.0);
  const render::DepthSensorModel model(only(true, false, true), k, 42);
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
  render::RgbdRenderer renderer(k);
  const render::DepthSensorModel model(scene::DepthSensorSpec{}, k, 7);
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
  const render::DepthSensorModel ideal(only(false, false, false), k, 7);
  const render::RenderedView mid = wall_view(renderer, 2.0);
  EXPECT_EQ(cv::norm(ideal.measure(mid, 0), mid.depth_m, cv::NORM_INF), 0.0);
}

TEST(DepthSensorModel, QuantisationPutsReadingsOnTheDisparityGrid) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  render::RgbdRenderer renderer(k);
  renderer.set_world(test::wall_facing_minus_x(3.0), {}, 1, scene::AppearanceThemes{});
  // Oblique view: a continuum of true depths between ~1.5 m and 4 m.
  const render::RenderedView view = renderer.render(camera_pose_from_planar(0.0, 0.0, 0.9, 0.0));
  const scene::DepthSensorSpec spec = only(false, true, false);
  const render::DepthSensorModel model(spec, k, 3);
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
  render::RgbdRenderer renderer(k);
  // A wall 0.35 m away, looked at almost along it: rays meet it at 44 to 90 deg from its
  // normal, and those beyond 82 deg still hit it within the 4 m range.
  renderer.set_world(test::wall_facing_minus_x(0.35), {}, 1, scene::AppearanceThemes{});
  const render::RenderedView view = renderer.render(camera_pose_from_planar(0.0, 0.0, 1.3, 0.0));
  const render::DepthSensorModel model(only(false, false, true), k, 3);
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
  render::RgbdRenderer renderer(k);
  const test::HandCorridor corridor = test::hand_corridor();
  renderer.set_world(corridor.mesh, corridor.lights, 1, scene::AppearanceThemes{});
  // Facing the pillar (x 13.0-13.4) from 2.5 m, with the end wall 9.5 m behind it; the range
  // limit is lifted so the far side of the edge would otherwise have a reading.
  const render::RenderedView view = renderer.render(camera_pose_from_planar(10.5, 0.0, 0.0, 1.0));
  scene::DepthSensorSpec spec = only(false, false, true);
  spec.max_range_m = 30.0;
  const render::DepthSensorModel model(spec, k, 3);
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
  render::RgbdRenderer renderer(k);
  const render::RenderedView view = wall_view(renderer, 2.0);
  const render::DepthSensorModel model(scene::DepthSensorSpec{}, k, 11);
  EXPECT_EQ(cv::norm(model.measure(view, 4), model.measure(view, 4), cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(model.measure(view, 4), model.measure(view, 5), cv::NORM_INF), 0.0);
  // The same numbers whatever the thread count.
  const cv::Mat parallel = model.measure(view, 4);
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);
  const cv::Mat serial = model.measure(view, 4);
  cv::setNumThreads(threads);
  EXPECT_EQ(cv::norm(parallel, serial, cv::NORM_INF), 0.0);
  const render::DepthSensorModel other_seed(scene::DepthSensorSpec{}, k, 12);
  EXPECT_GT(cv::norm(model.measure(view, 4), other_seed.measure(view, 4), cv::NORM_INF), 0.0);
}

// A synthetic ideal frame built from integer arithmetic only (the same floats on every machine):
// ramps in depth, holes, steps of 0.3-1 m (depth edges) and incidence |cos| on the renderer's
// 1/255 grid, some beyond the grazing limit.
struct SyntheticView {
  cv::Mat depth_m, incidence_cos;
};
SyntheticView synthetic_view() {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  SyntheticView s{cv::Mat(k.height_px, k.width_px, CV_32FC1),
                  cv::Mat(k.height_px, k.width_px, CV_32FC1)};
  for (int v = 0; v < k.height_px; ++v) {
    for (int u = 0; u < k.width_px; ++u) {
      const int band = (u / 80 + v / 60) % 4;
      float z = 0.6f + 0.5f * static_cast<float>(band) +
                static_cast<float>((u * 7 + v * 3) % 640) / 256.0f;
      if ((u / 40) % 7 == 3 && (v / 30) % 5 == 2) z = 0.0f;  // holes (nothing rendered)
      s.depth_m.at<float>(v, u) = z;
      s.incidence_cos.at<float>(v, u) =
          z > 0.0f ? static_cast<float>((u + 2 * v) % 256) / 255.0f : 0.0f;
    }
  }
  return s;
}

std::string digest_of(const cv::Mat& m) {
  CV_Assert(m.isContinuous());
  return sha256_hex(
      std::string_view(reinterpret_cast<const char*>(m.data), m.total() * m.elemSize()));
}

// The model's default output on a fixed input, recorded before lateral noise was added: with
// lateral noise off (the default), every pixel of every frame must stay what it was.
TEST(DepthSensorModel, DefaultOutputIsPinned) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  const SyntheticView view = synthetic_view();
  const render::DepthSensorModel model(scene::DepthSensorSpec{}, k, 2024);
  cv::Mat out;
  model.measure(view.depth_m, view.incidence_cos, 7, out);
  EXPECT_EQ(digest_of(out), "92ed6bc2986e6ab5f5ed882a85b2c46db9ce252794bd3c513bbe413292c3e2f7")
      << "the default depth model's output moved";
  // Lateral noise off means off, whatever its parameters say.
  scene::DepthSensorSpec off;
  off.lateral_noise_base_px = 3.0;
  off.lateral_noise_angle_coeff_px = 1.0;
  cv::Mat off_out;
  render::DepthSensorModel(off, k, 2024).measure(view.depth_m, view.incidence_cos, 7, off_out);
  EXPECT_EQ(cv::norm(off_out, out, cv::NORM_INF), 0.0);
  EXPECT_EQ(digest_of(view.depth_m),
            "73a9639305c0d4c327ad4269e8d2d5edc3bd968860632db3a90bb7de409a3e82")
      << "the synthetic input moved";
}

// A depth image that changes along one image axis only (a plane seen with its slope along that
// axis): z = 1 m + 4 mm per pixel, so the depth a pixel reads tells which column (or row) it came
// from. Incidence |cos| is uniform, on the renderer's 1/255 grid.
struct Ramp {
  cv::Mat depth_m, incidence_cos;
};
constexpr float kRampStartM = 1.0f, kRampStepM = 0.004f;
Ramp ramp(bool along_columns, int incidence_code) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  Ramp r{cv::Mat(k.height_px, k.width_px, CV_32FC1),
         cv::Mat(k.height_px, k.width_px, CV_32FC1,
                 cv::Scalar(static_cast<float>(incidence_code) / 255.0f))};
  for (int v = 0; v < k.height_px; ++v) {
    for (int u = 0; u < k.width_px; ++u) {
      r.depth_m.at<float>(v, u) =
          kRampStartM + kRampStepM * static_cast<float>(along_columns ? u : v);
    }
  }
  return r;
}

/// Nguyen, Izadi and Lovell 2012, written out here rather than taken from the model.
double nguyen_sigma_l_px(double theta_rad) {
  return 0.8 + 0.035 * theta_rad / (std::numbers::pi / 2 - theta_rad);
}

scene::DepthSensorSpec only_lateral() {
  scene::DepthSensorSpec spec = only(false, false, false);
  spec.lateral_noise = true;
  return spec;
}

TEST(DepthSensorModel, LateralShiftSpreadMatchesNguyenAtEachAngle) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  const render::DepthSensorModel model(only_lateral(), k, 5);
  // 0, 60, 75 and 80 deg (cos on the 1/255 grid); sigma_L from 0.80 to 1.08 px.
  for (const int code : {255, 128, 66, 44}) {
    const double theta = std::acos(code / 255.0);
    const double expected_px = nguyen_sigma_l_px(theta);
    for (const bool along_columns : {true, false}) {
      const Ramp r = ramp(along_columns, code);
      cv::Mat measured;
      model.measure(r.depth_m, r.incidence_cos, 3, measured);
      // Whole-pixel shift along the ramp's axis, away from the borders (where shifts are clamped).
      double sum = 0.0, sum_sq = 0.0, off_grid = 0.0;
      int n = 0;
      for (int v = 8; v < measured.rows - 8; ++v) {
        for (int u = 8; u < measured.cols - 8; ++u) {
          const double from = (measured.at<float>(v, u) - kRampStartM) / kRampStepM;
          const double shift = from - (along_columns ? u : v);
          off_grid = std::max(off_grid, std::abs(shift - std::round(shift)));
          sum += shift;
          sum_sq += shift * shift;
          ++n;
        }
      }
      const double mean = sum / n, stddev = std::sqrt(sum_sq / n - mean * mean);
      EXPECT_LT(off_grid, 0.01) << "shifts are whole pixels";
      EXPECT_NEAR(mean, 0.0, 0.01) << "code " << code;
      // ~290k shifts: the spread is known to ~0.15 %; 2 % tolerates the deviate table's finite
      // resolution and would catch a constant 0.8 px (10 % off at 75 deg) or a wrong rounding.
      EXPECT_NEAR(stddev, expected_px, 0.02 * expected_px)
          << "code " << code << (along_columns ? " along u" : " along v");
      EXPECT_NEAR(model.lateral_noise()->shift_stddev_px(code), expected_px, 2e-3);
    }
  }
}

TEST(DepthSensorModel, LateralShiftMakesDepthEdgesRaggedBySigmaL) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  // Vertical stripes 16 px wide, alternately 1.5 m and 3 m away: 39 straight vertical depth
  // edges, seen at theta = acos(200/255) = 38 deg.
  constexpr int kStripe = 16, kCode = 200;
  cv::Mat depth(k.height_px, k.width_px, CV_32FC1);
  for (int u = 0; u < k.width_px; ++u) depth.col(u).setTo((u / kStripe) % 2 ? 3.0f : 1.5f);
  const cv::Mat cos(k.height_px, k.width_px, CV_32FC1, cv::Scalar(kCode / 255.0f));
  const render::DepthSensorModel model(only_lateral(), k, 9);
  const render::DepthSensorModel straight(only(false, false, false), k, 9);
  // swapped[k - 1][side]: pixels k columns left of an edge (side 0) or k - 1 right of it
  // (side 1) that read the other side's depth.
  std::array<std::array<double, 2>, 4> swapped{};
  int ragged_rows = 0, rows = 0;
  constexpr int kFrames = 10;
  for (int frame = 0; frame < kFrames; ++frame) {
    cv::Mat z;
    model.measure(depth, cos, frame, z);
    for (int v = 0; v < z.rows; ++v) {
      bool ragged = false;
      for (int edge = kStripe; edge < z.cols; edge += kStripe) {
        for (int d = 1; d <= 4; ++d) {
          const bool left = z.at<float>(v, edge - d) != depth.at<float>(v, edge - d);
          const bool right = z.at<float>(v, edge + d - 1) != depth.at<float>(v, edge + d - 1);
          swapped[d - 1][0] += left;
          swapped[d - 1][1] += right;
          ragged = ragged || left || right;
        }
      }
      ragged_rows += ragged;
      ++rows;
    }
  }
  const double edges_seen = static_cast<double>(rows) * (k.width_px / kStripe - 1);
  // Edge displacement spread: Var(dx) = sum_d (2d - 1) (P(dx >= d) + P(dx <= -d)), where a pixel
  // d columns left of an edge reads across it iff dx >= d, and d - 1 right of it iff dx <= -d.
  double variance = 0.0;
  for (int d = 1; d <= 4; ++d) {
    variance += (2.0 * d - 1.0) * (swapped[d - 1][0] + swapped[d - 1][1]) / edges_seen;
  }
  const double expected_px = nguyen_sigma_l_px(std::acos(kCode / 255.0));
  // ~190k edge crossings: the spread is known to ~1 %; 3 % tolerance.
  EXPECT_NEAR(std::sqrt(variance), expected_px, 0.03 * expected_px);
  // Symmetric: as many pixels cross from the near side as from the far side.
  EXPECT_NEAR(swapped[0][0] / edges_seen, swapped[0][1] / edges_seen, 0.01);
  EXPECT_GT(ragged_rows, rows * 9 / 10) << "almost every row has a ragged edge";
  // Without lateral noise the edges stay straight.
  cv::Mat z;
  straight.measure(depth, cos, 0, z);
  EXPECT_EQ(cv::norm(z, depth, cv::NORM_INF), 0.0);
}

TEST(DepthSensorModel, LateralShiftIsItsOwnStreamAndIgnoresThreads) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  // On a plane facing the camera a shift changes nothing, so with lateral noise on the axial
  // noise must be exactly what it was without it (its own random stream).
  const cv::Mat flat(k.height_px, k.width_px, CV_32FC1, cv::Scalar(2.0f));
  const cv::Mat facing(k.height_px, k.width_px, CV_32FC1, cv::Scalar(1.0f));
  scene::DepthSensorSpec with = scene::DepthSensorSpec{};
  with.lateral_noise = true;
  const render::DepthSensorModel lateral(with, k, 21), plain(scene::DepthSensorSpec{}, k, 21);
  cv::Mat a, b;
  lateral.measure(flat, facing, 4, a);
  plain.measure(flat, facing, 4, b);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  // On a ramp: the same frame gives the same shifts, another frame others, whatever the threads.
  const Ramp r = ramp(true, 255);
  cv::Mat first, again, other;
  lateral.measure(r.depth_m, r.incidence_cos, 4, first);
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);
  lateral.measure(r.depth_m, r.incidence_cos, 4, again);
  cv::setNumThreads(threads);
  lateral.measure(r.depth_m, r.incidence_cos, 5, other);
  EXPECT_EQ(cv::norm(first, again, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(first, other, cv::NORM_INF), 0.0);
}

TEST(DepthSensorModel, RejectsInconsistentParameters) {
  scene::DepthSensorSpec spec;
  spec.min_range_m = 5.0;
  EXPECT_THROW(render::DepthSensorModel(spec, CameraIntrinsics::kinect_v1(), 1), InvalidInputError);
  spec = scene::DepthSensorSpec{};
  spec.disparity_step_px = 0.0;
  EXPECT_THROW(render::DepthSensorModel(spec, CameraIntrinsics::kinect_v1(), 1), InvalidInputError);
  spec = scene::DepthSensorSpec{};
  spec.lateral_noise = true;
  spec.lateral_noise_base_px = -0.1;
  EXPECT_THROW(render::DepthSensorModel(spec, CameraIntrinsics::kinect_v1(), 1), InvalidInputError);
  spec.lateral_noise_base_px = 0.8;
  spec.grazing_dropout_deg = 90.0;  // the cap on theta: sigma_L is infinite there
  EXPECT_THROW(render::DepthSensorModel(spec, CameraIntrinsics::kinect_v1(), 1), InvalidInputError);
}

}  // namespace
}  // namespace wifislam::sim
