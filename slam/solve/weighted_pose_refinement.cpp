#include "slam/solve/weighted_pose_refinement.hpp"

#include <ceres/autodiff_cost_function.h>
#include <ceres/ceres.h>

#include <Eigen/Geometry>

namespace wifislam::slam::solve {

namespace {

class WhitenedReprojectionError {
 public:
  WhitenedReprojectionError(const Eigen::Vector3d& point_b, const Eigen::Vector2d& pixel_a,
                            const Eigen::Matrix2d& sqrt_information,
                            const CameraIntrinsics& intrinsics)
      : point_b_(point_b),
        pixel_a_(pixel_a),
        sqrt_information_(sqrt_information),
        fx_(intrinsics.fx_px),
        fy_(intrinsics.fy_px),
        cx_(intrinsics.cx_px),
        cy_(intrinsics.cy_px) {}

  template <typename T>
  bool operator()(const T* q_ptr, const T* t_ptr, T* residuals_ptr) const {
    const Eigen::Map<const Eigen::Quaternion<T>> q(q_ptr);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> t(t_ptr);
    const Eigen::Matrix<T, 3, 1> x = q * point_b_.cast<T>() + t;
    Eigen::Matrix<T, 2, 1> r;
    r(0) = T(fx_) * x(0) / x(2) + T(cx_) - T(pixel_a_(0));
    r(1) = T(fy_) * x(1) / x(2) + T(cy_) - T(pixel_a_(1));
    Eigen::Map<Eigen::Matrix<T, 2, 1>> residuals(residuals_ptr);
    residuals = sqrt_information_.cast<T>() * r;
    return true;
  }

 private:
  Eigen::Vector3d point_b_;
  Eigen::Vector2d pixel_a_;
  Eigen::Matrix2d sqrt_information_;
  double fx_, fy_, cx_, cy_;
};

}  // namespace

Eigen::Matrix2d projected_point_covariance(const Eigen::Vector3d& point_b_m, const Pose& a_from_b,
                                           const CameraIntrinsics& intrinsics, double sigma_px,
                                           double depth_noise_coeff_per_m) {
  const Eigen::Vector3d x = a_from_b * point_b_m;
  Eigen::Matrix2d covariance = sigma_px * sigma_px * Eigen::Matrix2d::Identity();
  if (x.z() <= 1e-6 || point_b_m.z() <= 1e-6) return covariance;
  const double iz = 1.0 / x.z();
  Eigen::Matrix<double, 2, 3> dpi;
  dpi << intrinsics.fx_px * iz, 0, -intrinsics.fx_px * x.x() * iz * iz,  //
      0, intrinsics.fy_px * iz, -intrinsics.fy_px * x.y() * iz * iz;
  // A depth error dz moves the point along b's ray by (X_b / z_b) dz.
  const double sigma_z = depth_noise_coeff_per_m * point_b_m.z() * point_b_m.z();
  const Eigen::Vector2d shift = dpi * (a_from_b.linear() * (point_b_m / point_b_m.z())) * sigma_z;
  covariance += shift * shift.transpose();
  return covariance;
}

Pose refine_pose_weighted(const std::vector<Eigen::Vector3d>& points_b_m,
                          const std::vector<Eigen::Vector2d>& pixels_a, const Pose& initial,
                          const CameraIntrinsics& intrinsics, double sigma_px,
                          double depth_noise_coeff_per_m, int max_iterations) {
  Eigen::Quaterniond q(initial.linear());
  q.normalize();
  Eigen::Vector3d t = initial.translation();
  ceres::Problem problem;
  problem.AddParameterBlock(q.coeffs().data(), 4, new ceres::EigenQuaternionManifold);
  problem.AddParameterBlock(t.data(), 3);
  for (std::size_t i = 0; i < points_b_m.size(); ++i) {
    const Eigen::Matrix2d covariance = projected_point_covariance(
        points_b_m[i], initial, intrinsics, sigma_px, depth_noise_coeff_per_m);
    const Eigen::Matrix2d sqrt_information =
        Eigen::LLT<Eigen::Matrix2d>(covariance.inverse()).matrixU();
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<WhitenedReprojectionError, 2, 4, 3>(
                                 new WhitenedReprojectionError(points_b_m[i], pixels_a[i],
                                                               sqrt_information, intrinsics)),
                             nullptr, q.coeffs().data(), t.data());
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = max_iterations;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  if (!summary.IsSolutionUsable()) return initial;
  return pose_from_translation_quaternion(t, q);
}

}  // namespace wifislam::slam::solve
