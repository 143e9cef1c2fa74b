#include "slam/solve/visual_transformation.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

#include "core/error.hpp"
#include "slam/solve/weighted_pose_refinement.hpp"

namespace wifislam::slam::solve {

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

/// The matched keypoints as PnP sees them: frame b's 3-D points, frame a's pixels, and the depth
/// frame a measured at each (0 = none).
struct Correspondences {
  std::vector<cv::Point3d> object_points;
  std::vector<cv::Point2d> image_points;
  std::vector<double> depth_a_m;
};

Correspondences correspondences_of(const feature::FrameFeatures& a, const feature::FrameFeatures& b,
                                   const std::vector<match::FeatureMatch>& matches) {
  Correspondences c;
  c.object_points.reserve(matches.size());
  c.image_points.reserve(matches.size());
  c.depth_a_m.reserve(matches.size());
  for (const match::FeatureMatch& m : matches) {
    const Eigen::Vector3d& p = b.points_m[static_cast<std::size_t>(m.train)];
    const auto q = static_cast<std::size_t>(m.query);
    const cv::Point2f& u = a.keypoints[q].pt;
    c.object_points.emplace_back(p.x(), p.y(), p.z());
    c.image_points.emplace_back(u.x, u.y);
    c.depth_a_m.push_back(a.has_depth[q] ? a.points_m[q].z() : 0.0);
  }
  return c;
}

/// Picks the correspondences a pose explains. An inlier reprojects within inlier_distance and,
/// where frame a measured depth too, lands at that depth within the sensor's noise: this rejects
/// poses that only look right in 2-D (the mirror solution of a planar floor, a shift by one
/// period of a repeated texture). Keeps the projections of its last call for the residuals.
class InlierSelector {
 public:
  InlierSelector(const Correspondences& correspondences, const CameraIntrinsics& intrinsics,
                 const VisualTransformOptions& options)
      : c_(correspondences),
        intrinsics_(intrinsics),
        options_(options),
        threshold_sq_(options.inlier_distance * options.inlier_distance),
        projected_(correspondences.object_points.size()) {}

  /// Indices (ascending) of the correspondences that are inliers of `pose` (a_from_b).
  std::vector<int> select(const Pose& pose) {
    std::vector<int> selected;
    for (std::size_t i = 0; i < c_.object_points.size(); ++i) {
      const cv::Point3d& p = c_.object_points[i];
      const Eigen::Vector3d x = pose * Eigen::Vector3d(p.x, p.y, p.z);
      projected_[i] = cv::Point2d(-1e9, -1e9);
      if (x.z() <= 1e-6) continue;  // behind frame a: not a correspondence
      projected_[i] = {intrinsics_.fx_px * x.x() / x.z() + intrinsics_.cx_px,
                       intrinsics_.fy_px * x.y() / x.z() + intrinsics_.cy_px};
      const cv::Point2d d = projected_[i] - c_.image_points[i];
      if (d.dot(d) >= threshold_sq_) continue;
      if (options_.depth_consistency_sigmas > 0 && c_.depth_a_m[i] > 0) {
        const double za = c_.depth_a_m[i], zb = p.z;
        const double sigma_m = options_.depth_noise_coeff_per_m * std::hypot(za * za, zb * zb);
        const double tolerance_m = options_.depth_consistency_sigmas * sigma_m + 0.02;
        if (std::abs(x.z() - za) > tolerance_m) continue;
      }
      selected.push_back(static_cast<int>(i));
    }
    return selected;
  }

  /// Where the last select() projected correspondence `i` into frame a.
  const cv::Point2d& projected(std::size_t i) const { return projected_[i]; }

 private:
  const Correspondences& c_;
  const CameraIntrinsics& intrinsics_;
  const VisualTransformOptions& options_;
  double threshold_sq_;
  std::vector<cv::Point2d> projected_;
};

std::vector<match::FeatureMatch> timed_matches(const feature::FrameFeatures& a,
                                               const feature::FrameFeatures& b,
                                               const VisualTransformOptions& options,
                                               util::Instrumentation& instrumentation) {
  util::ScopedTimer timer(instrumentation, module::kMatching);
  return match::match_descriptors(a, b, options.matching);
}

/// EPnP in RANSAC; false when it finds no pose with at least min_matches inliers.
bool ransac_pose(const Correspondences& c, const cv::Mat& k, const VisualTransformOptions& options,
                 cv::Mat& rvec, cv::Mat& tvec) {
  std::vector<int> ransac_inliers;
  const bool found =
      cv::solvePnPRansac(c.object_points, c.image_points, k, cv::noArray(), rvec, tvec, false,
                         options.ransac_iterations, static_cast<float>(options.inlier_distance),
                         options.ransac_confidence, ransac_inliers, cv::SOLVEPNP_EPNP);
  return found && static_cast<int>(ransac_inliers.size()) >= options.min_matches;
}

/// Refines on the inliers, re-selects inliers with the refined pose, refines once more (and
/// re-selects). False as soon as fewer than `min_matches` inliers are left.
bool refine_on_inliers(const Correspondences& c, const cv::Mat& k, int min_matches,
                       InlierSelector& selector, cv::Mat& rvec, cv::Mat& tvec,
                       std::vector<int>& inliers) {
  inliers = selector.select(pose_from_rvec_tvec(rvec, tvec));
  if (static_cast<int>(inliers.size()) < min_matches) return false;
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<cv::Point3d> obj;
    std::vector<cv::Point2d> img;
    for (int i : inliers) {
      obj.push_back(c.object_points[static_cast<std::size_t>(i)]);
      img.push_back(c.image_points[static_cast<std::size_t>(i)]);
    }
    cv::solvePnPRefineLM(obj, img, k, cv::noArray(), rvec, tvec);
    inliers = selector.select(pose_from_rvec_tvec(rvec, tvec));
    if (static_cast<int>(inliers.size()) < min_matches) return false;
  }
  return true;
}

/// Final refinement with every inlier weighted by its depth uncertainty (nominal 1 px keypoint
/// noise), from `initial`.
Pose refine_weighted(const Correspondences& c, const std::vector<int>& inliers, const Pose& initial,
                     const CameraIntrinsics& intrinsics, const VisualTransformOptions& options) {
  std::vector<Eigen::Vector3d> points_b;
  std::vector<Eigen::Vector2d> pixels_a;
  for (int i : inliers) {
    const cv::Point3d& p = c.object_points[static_cast<std::size_t>(i)];
    const cv::Point2d& u = c.image_points[static_cast<std::size_t>(i)];
    points_b.emplace_back(p.x, p.y, p.z);
    pixels_a.emplace_back(u.x, u.y);
  }
  return refine_pose_weighted(points_b, pixels_a, initial, intrinsics, 1.0,
                              options.depth_noise_coeff_per_m);
}

/// Accepts `result` (its a_from_b already set) with the final inliers: their count, RMS
/// reprojection error and the information of the pose.
void accept(const Correspondences& c, const std::vector<int>& inliers,
            const InlierSelector& selector, const CameraIntrinsics& intrinsics,
            const VisualTransformOptions& options, VisualTransformation& result) {
  double sum_sq = 0.0;
  std::vector<Eigen::Vector3d> inlier_points_b;
  inlier_points_b.reserve(inliers.size());
  for (int i : inliers) {
    const cv::Point2d d = selector.projected(static_cast<std::size_t>(i)) -
                          c.image_points[static_cast<std::size_t>(i)];
    sum_sq += d.dot(d);
    const cv::Point3d& p = c.object_points[static_cast<std::size_t>(i)];
    inlier_points_b.emplace_back(p.x, p.y, p.z);
  }
  result.inliers = static_cast<int>(inliers.size());
  result.rms_reprojection_px = std::sqrt(sum_sq / result.inliers);
  // Per-axis residual variance: the squared 2-D residual has two components.
  const double sigma_px =
      std::max(options.min_reprojection_sigma_px, std::sqrt(sum_sq / (2.0 * result.inliers)));
  result.information =
      options.information_scale * pnp_information(inlier_points_b, result.a_from_b, intrinsics,
                                                  sigma_px, options.depth_noise_coeff_per_m);
  result.accepted = true;
}

}  // namespace

Eigen::Matrix<double, 6, 6> pnp_information(const std::vector<Eigen::Vector3d>& points_in_b_m,
                                            const Pose& a_from_b,
                                            const CameraIntrinsics& intrinsics, double sigma_px,
                                            double depth_noise_coeff_per_m) {
  // Perturbation xi = (dt, dtheta) on the left of a_from_b, in frame a: X_a' = X_a + dtheta x X_a
  // + dt. Projection Jacobian J_i = dpi/dX [I, -[X_a]x]; information in xi is sum J^T W J.
  Eigen::Matrix<double, 6, 6> info_xi = Eigen::Matrix<double, 6, 6>::Zero();
  for (const Eigen::Vector3d& x_b : points_in_b_m) {
    const Eigen::Vector3d x = a_from_b * x_b;
    if (x.z() <= 1e-6 || x_b.z() <= 1e-6) continue;
    const double iz = 1.0 / x.z();
    Eigen::Matrix<double, 2, 3> dpi;
    dpi << intrinsics.fx_px * iz, 0, -intrinsics.fx_px * x.x() * iz * iz,  //
        0, intrinsics.fy_px * iz, -intrinsics.fy_px * x.y() * iz * iz;
    Eigen::Matrix<double, 3, 6> dx;
    dx << Eigen::Matrix3d::Identity(), -skew(x);
    const Eigen::Matrix<double, 2, 6> j = dpi * dx;
    const Eigen::Matrix2d covariance =
        projected_point_covariance(x_b, a_from_b, intrinsics, sigma_px, depth_noise_coeff_per_m);
    info_xi += j.transpose() * covariance.inverse() * j;
  }
  // The pose graph residual r = [p_est - p_meas; 2 vec(q_meas q_est^-1)] linearises to r = A xi
  // with A = [I, -[p]x; 0, -I], and A^-1 = A, so the information in r is A^T info_xi A.
  Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero();
  a.topLeftCorner<3, 3>().setIdentity();
  a.topRightCorner<3, 3>() = -skew(a_from_b.translation());
  a.bottomRightCorner<3, 3>() = -Eigen::Matrix3d::Identity();
  Eigen::Matrix<double, 6, 6> info = a.transpose() * info_xi * a;
  return 0.5 * (info + info.transpose());
}

VisualTransformation estimate_visual_transformation(const feature::FrameFeatures& a,
                                                    const feature::FrameFeatures& b,
                                                    const CameraIntrinsics& intrinsics,
                                                    const VisualTransformOptions& options,
                                                    util::Instrumentation& instrumentation) {
  if (!(options.ransac_confidence > 0.0 && options.ransac_confidence < 1.0)) {
    throw InvalidInputError("ransac_confidence must be in (0, 1), got " +
                            std::to_string(options.ransac_confidence));
  }
  VisualTransformation result;
  const std::vector<match::FeatureMatch> matches = timed_matches(a, b, options, instrumentation);
  result.matches = static_cast<int>(matches.size());
  // Fewer matches than required inliers can never be accepted: skip RANSAC.
  if (result.matches < std::max(options.min_matches, 6)) return result;

  util::ScopedTimer timer(instrumentation, module::kRansac);
  instrumentation.count(counter::kRansacRuns);
  const Correspondences c = correspondences_of(a, b, matches);
  cv::Mat k;
  cv::eigen2cv(intrinsics.matrix(), k);
  cv::Mat rvec, tvec;
  if (!ransac_pose(c, k, options, rvec, tvec)) return result;
  InlierSelector selector(c, intrinsics, options);
  std::vector<int> inliers;
  if (!refine_on_inliers(c, k, options.min_matches, selector, rvec, tvec, inliers)) return result;
  result.a_from_b =
      refine_weighted(c, inliers, pose_from_rvec_tvec(rvec, tvec), intrinsics, options);
  if (!result.a_from_b.matrix().allFinite()) return result;
  inliers = selector.select(result.a_from_b);
  if (static_cast<int>(inliers.size()) < options.min_matches) return result;
  accept(c, inliers, selector, intrinsics, options, result);
  instrumentation.count(counter::kAcceptedTransformations);
  return result;
}

}  // namespace wifislam::slam::solve
