#include "slam/solve/visual_transformation.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

#include "core/error.hpp"

namespace wifislam::slam {

namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

Pose pose_from_rvec_tvec(const cv::Mat& rvec, const cv::Mat& tvec) {
  cv::Mat r;
  cv::Rodrigues(rvec, r);
  Eigen::Matrix3d rotation;
  cv::cv2eigen(r, rotation);
  Pose pose = Pose::Identity();
  pose.linear() = rotation;
  pose.translation() = Eigen::Vector3d(tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2));
  return pose;
}

}  // namespace

Eigen::Matrix<double, 6, 6> pnp_information(const std::vector<Eigen::Vector3d>& points_in_a_m,
                                            const Pose& a_from_b,
                                            const CameraIntrinsics& intrinsics, double sigma_px) {
  // Perturbation xi = (dt, dtheta) on the left of a_from_b, in frame a: X_a' = X_a + dtheta x X_a
  // + dt. Projection Jacobian J_i = dpi/dX [I, -[X_a]x]; information in xi is sum J^T J / s^2.
  Eigen::Matrix<double, 6, 6> info_xi = Eigen::Matrix<double, 6, 6>::Zero();
  for (const Eigen::Vector3d& x : points_in_a_m) {
    if (x.z() <= 1e-6) continue;
    const double iz = 1.0 / x.z();
    Eigen::Matrix<double, 2, 3> dpi;
    dpi << intrinsics.fx_px * iz, 0, -intrinsics.fx_px * x.x() * iz * iz,  //
        0, intrinsics.fy_px * iz, -intrinsics.fy_px * x.y() * iz * iz;
    Eigen::Matrix<double, 3, 6> dx;
    dx << Eigen::Matrix3d::Identity(), -skew(x);
    const Eigen::Matrix<double, 2, 6> j = dpi * dx;
    info_xi += j.transpose() * j;
  }
  info_xi /= sigma_px * sigma_px;
  // The pose graph residual r = [p_est - p_meas; 2 vec(q_meas q_est^-1)] linearises to r = A xi
  // with A = [I, -[p]x; 0, -I], and A^-1 = A, so the information in r is A^T info_xi A.
  Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero();
  a.topLeftCorner<3, 3>().setIdentity();
  a.topRightCorner<3, 3>() = -skew(a_from_b.translation());
  a.bottomRightCorner<3, 3>() = -Eigen::Matrix3d::Identity();
  Eigen::Matrix<double, 6, 6> info = a.transpose() * info_xi * a;
  return 0.5 * (info + info.transpose());
}

VisualTransformation estimate_visual_transformation(const FrameFeatures& a, const FrameFeatures& b,
                                                    const CameraIntrinsics& intrinsics,
                                                    const VisualTransformOptions& options,
                                                    Instrumentation& instrumentation) {
  if (!(options.ransac_confidence > 0.0 && options.ransac_confidence < 1.0)) {
    throw InvalidInputError("ransac_confidence must be in (0, 1), got " +
                            std::to_string(options.ransac_confidence));
  }
  VisualTransformation result;
  std::vector<FeatureMatch> matches;
  {
    ScopedTimer timer(instrumentation, module::kMatching);
    matches = match_descriptors(a, b, options.matching);
  }
  result.matches = static_cast<int>(matches.size());
  // Fewer matches than required inliers can never be accepted: skip RANSAC.
  if (result.matches < std::max(options.min_matches, 6)) return result;

  ScopedTimer timer(instrumentation, module::kRansac);
  instrumentation.count(counter::kRansacRuns);
  std::vector<cv::Point3d> object_points;
  std::vector<cv::Point2d> image_points;
  object_points.reserve(matches.size());
  image_points.reserve(matches.size());
  for (const FeatureMatch& m : matches) {
    const Eigen::Vector3d& p = b.points_m[static_cast<std::size_t>(m.train)];
    const cv::Point2f& u = a.keypoints[static_cast<std::size_t>(m.query)].pt;
    object_points.emplace_back(p.x(), p.y(), p.z());
    image_points.emplace_back(u.x, u.y);
  }
  cv::Mat k;
  cv::eigen2cv(intrinsics.matrix(), k);
  cv::Mat rvec, tvec;
  std::vector<int> ransac_inliers;
  const bool found =
      cv::solvePnPRansac(object_points, image_points, k, cv::noArray(), rvec, tvec, false,
                         options.ransac_iterations, static_cast<float>(options.inlier_distance),
                         options.ransac_confidence, ransac_inliers, cv::SOLVEPNP_EPNP);
  if (!found || static_cast<int>(ransac_inliers.size()) < options.min_matches) return result;

  // Refine on the inliers, re-select inliers with the refined pose, refine once more.
  std::vector<int> inliers = ransac_inliers;
  const double threshold_sq = options.inlier_distance * options.inlier_distance;
  std::vector<cv::Point2d> projected;
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<cv::Point3d> obj;
    std::vector<cv::Point2d> img;
    for (int i : inliers) {
      obj.push_back(object_points[static_cast<std::size_t>(i)]);
      img.push_back(image_points[static_cast<std::size_t>(i)]);
    }
    cv::solvePnPRefineLM(obj, img, k, cv::noArray(), rvec, tvec);
    const Pose pose = pose_from_rvec_tvec(rvec, tvec);
    projected.assign(object_points.size(), cv::Point2d(-1e9, -1e9));
    inliers.clear();
    for (std::size_t i = 0; i < object_points.size(); ++i) {
      const cv::Point3d& p = object_points[i];
      const Eigen::Vector3d x = pose * Eigen::Vector3d(p.x, p.y, p.z);
      if (x.z() <= 1e-6) continue;  // behind frame a: not a correspondence, whatever it projects to
      projected[i] = {intrinsics.fx_px * x.x() / x.z() + intrinsics.cx_px,
                      intrinsics.fy_px * x.y() / x.z() + intrinsics.cy_px};
      const cv::Point2d d = projected[i] - image_points[i];
      if (d.dot(d) < threshold_sq) inliers.push_back(static_cast<int>(i));
    }
    if (static_cast<int>(inliers.size()) < options.min_matches) return result;
  }

  result.a_from_b = pose_from_rvec_tvec(rvec, tvec);
  if (!result.a_from_b.matrix().allFinite()) return result;
  double sum_sq = 0.0;
  std::vector<Eigen::Vector3d> points_in_a;
  points_in_a.reserve(inliers.size());
  for (int i : inliers) {
    const cv::Point2d d =
        projected[static_cast<std::size_t>(i)] - image_points[static_cast<std::size_t>(i)];
    sum_sq += d.dot(d);
    const cv::Point3d& p = object_points[static_cast<std::size_t>(i)];
    points_in_a.push_back(result.a_from_b * Eigen::Vector3d(p.x, p.y, p.z));
  }
  result.inliers = static_cast<int>(inliers.size());
  result.rms_reprojection_px = std::sqrt(sum_sq / result.inliers);
  // Per-axis residual variance: the squared 2-D residual has two components.
  const double sigma_px =
      std::max(options.min_reprojection_sigma_px, std::sqrt(sum_sq / (2.0 * result.inliers)));
  result.information = pnp_information(points_in_a, result.a_from_b, intrinsics, sigma_px);
  result.accepted = true;
  instrumentation.count(counter::kAcceptedTransformations);
  return result;
}

}  // namespace wifislam::slam
