#include "eval/view_overlap.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wifislam::eval {

DepthView make_depth_view(const cv::Mat& depth_m, const CameraIntrinsics& intrinsics,
                          const EvalOptions& options) {
  DepthView view;
  const int sample = options.overlap_sample_stride_px, lookup = options.overlap_lookup_stride_px;
  view.lookup_stride_px = lookup;
  for (int v = sample / 2; v < depth_m.rows; v += sample) {
    const float* row = depth_m.ptr<float>(v);
    for (int u = sample / 2; u < depth_m.cols; u += sample) {
      const float z = row[u];
      if (z > 0.0f && std::isfinite(z)) {
        view.samples_camera_m.push_back(intrinsics.back_project(u, v, z).cast<float>());
      }
    }
  }
  const int rows = (depth_m.rows + lookup - 1) / lookup,
            cols = (depth_m.cols + lookup - 1) / lookup;
  view.lookup_depth_m.create(rows, cols, CV_32FC1);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const float z = depth_m.at<float>(r * lookup, c * lookup);
      view.lookup_depth_m.at<float>(r, c) = std::isfinite(z) ? z : 0.0f;
    }
  }
  return view;
}

double landing_fraction(const DepthView& a, const Pose& a_to_world, const DepthView& b,
                        const Pose& b_to_world, const CameraIntrinsics& k,
                        const EvalOptions& options) {
  if (a.samples_camera_m.empty()) return 0.0;
  const Eigen::Matrix4f b_from_a = (b_to_world.inverse() * a_to_world).matrix().cast<float>();
  const Eigen::Matrix3f rotation = b_from_a.topLeftCorner<3, 3>();
  const Eigen::Vector3f translation = b_from_a.topRightCorner<3, 1>();
  const float stride = static_cast<float>(b.lookup_stride_px);
  const int rows = b.lookup_depth_m.rows, cols = b.lookup_depth_m.cols;
  std::size_t landed = 0;
  for (const Eigen::Vector3f& p_a : a.samples_camera_m) {
    const Eigen::Vector3f p = rotation * p_a + translation;
    if (p.z() <= 0.0f) continue;
    const float u = static_cast<float>(k.fx_px) * p.x() / p.z() + static_cast<float>(k.cx_px);
    const float v = static_cast<float>(k.fy_px) * p.y() / p.z() + static_cast<float>(k.cy_px);
    // Inside the image (pixel centres at integer coordinates, as in back_project).
    if (u < -0.5f || v < -0.5f || u >= k.width_px - 0.5f || v >= k.height_px - 0.5f) continue;
    const int c = std::clamp(static_cast<int>(std::lround(u / stride)), 0, cols - 1);
    const int r = std::clamp(static_cast<int>(std::lround(v / stride)), 0, rows - 1);
    const float z_b = b.lookup_depth_m.at<float>(r, c);
    if (z_b <= 0.0f) continue;
    const double tolerance =
        std::max(options.overlap_depth_tolerance_m, options.overlap_depth_tolerance_rel * p.z());
    if (std::abs(static_cast<double>(z_b - p.z())) <= tolerance) ++landed;
  }
  return static_cast<double>(landed) / static_cast<double>(a.samples_camera_m.size());
}

ViewOverlap view_overlap(const Pose& a_to_world, const DepthView* a_depth, const Pose& b_to_world,
                         const DepthView* b_depth, const CameraIntrinsics& intrinsics,
                         const EvalOptions& options) {
  ViewOverlap out;
  out.distance_m = (a_to_world.translation() - b_to_world.translation()).norm();
  // Optical axis = camera z in the world.
  const Eigen::Vector3d za = a_to_world.linear().col(2), zb = b_to_world.linear().col(2);
  out.angle_deg = std::acos(std::clamp(za.dot(zb) / (za.norm() * zb.norm()), -1.0, 1.0)) * 180.0 /
                  std::numbers::pi;
  out.within_geometric_bound = out.distance_m <= options.overlap_max_distance_m &&
                               out.angle_deg <= options.overlap_max_angle_deg;
  if (!out.within_geometric_bound) return out;
  if (a_depth == nullptr || b_depth == nullptr) {
    out.overlap = true;
    return out;
  }
  out.depth_checked = true;
  out.fraction = landing_fraction(*a_depth, a_to_world, *b_depth, b_to_world, intrinsics, options);
  if (out.fraction < options.overlap_min_fraction) {
    out.fraction = std::max(out.fraction, landing_fraction(*b_depth, b_to_world, *a_depth,
                                                           a_to_world, intrinsics, options));
  }
  out.overlap = out.fraction >= options.overlap_min_fraction;
  return out;
}

}  // namespace wifislam::eval
