#pragma once
// Residual of one pose-graph edge, in the form of Ceres' pose_graph_3d example: for nodes a, b
// with positions p and unit quaternions q (Eigen order x, y, z, w),
//   r = sqrt_info * [q_a^-1 (p_b - p_a) - p_ab; 2 vec(q_ab q_est^-1)],  q_est = q_a^-1 q_b.

#include <ceres/autodiff_cost_function.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/pose.hpp"
#include "slam/graph/pose_graph.hpp"

namespace wifislam::slam::optimize {

class RelativePoseError {
 public:
  RelativePoseError(const Pose& a_from_b, const Eigen::Matrix<double, 6, 6>& sqrt_information)
      : p_ab_(a_from_b.translation()),
        q_ab_(Eigen::Quaterniond(a_from_b.linear()).normalized()),
        sqrt_information_(sqrt_information) {}

  template <typename T>
  bool operator()(const T* p_a_ptr, const T* q_a_ptr, const T* p_b_ptr, const T* q_b_ptr,
                  T* residuals_ptr) const {
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> p_a(p_a_ptr), p_b(p_b_ptr);
    const Eigen::Map<const Eigen::Quaternion<T>> q_a(q_a_ptr), q_b(q_b_ptr);
    const Eigen::Quaternion<T> q_a_inverse = q_a.conjugate();
    const Eigen::Quaternion<T> q_ab_estimated = q_a_inverse * q_b;
    const Eigen::Matrix<T, 3, 1> p_ab_estimated = q_a_inverse * (p_b - p_a);
    const Eigen::Quaternion<T> delta_q = q_ab_.template cast<T>() * q_ab_estimated.conjugate();
    Eigen::Map<Eigen::Matrix<T, 6, 1>> residuals(residuals_ptr);
    residuals.template head<3>() = p_ab_estimated - p_ab_.template cast<T>();
    residuals.template tail<3>() = T(2.0) * delta_q.vec();
    residuals.applyOnTheLeft(sqrt_information_.template cast<T>());
    return true;
  }

  static ceres::CostFunction* create(const Pose& a_from_b,
                                     const Eigen::Matrix<double, 6, 6>& sqrt_information) {
    return new ceres::AutoDiffCostFunction<RelativePoseError, 6, 3, 4, 3, 4>(
        new RelativePoseError(a_from_b, sqrt_information));
  }

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW

 private:
  Eigen::Vector3d p_ab_;
  Eigen::Quaterniond q_ab_;
  Eigen::Matrix<double, 6, 6> sqrt_information_;
};

/// Upper-triangular square root S of an information matrix (S^T S = info); eigenvalues below
/// `min_eigenvalue` are raised to it so a rank-deficient estimate still gives a valid factor.
Eigen::Matrix<double, 6, 6> information_square_root(const graph::Information6& information,
                                                    double min_eigenvalue = 1e-9);

}  // namespace wifislam::slam::optimize
