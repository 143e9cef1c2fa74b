#include "tests/slam/trajectory_error.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace wifislam::test {

AlignedError aligned_translation_error(const Trajectory& estimate,
                                       const std::map<std::int64_t, Pose>& truth) {
  std::vector<Eigen::Vector3d> est, gt;
  for (const StampedPose& p : estimate) {
    const auto it = truth.find(p.time.ns);
    if (it == truth.end()) continue;
    est.push_back(p.translation_m);
    gt.push_back(it->second.translation());
  }
  AlignedError out;
  out.pairs = est.size();
  if (est.size() < 3) return out;
  Eigen::Matrix3Xd a(3, est.size()), b(3, gt.size());
  for (std::size_t i = 0; i < est.size(); ++i) {
    a.col(static_cast<Eigen::Index>(i)) = est[i];
    b.col(static_cast<Eigen::Index>(i)) = gt[i];
  }
  const Eigen::Matrix4d t = Eigen::umeyama(a, b, false);
  double sum_sq = 0.0;
  for (std::size_t i = 0; i < est.size(); ++i) {
    const Eigen::Vector3d aligned = t.topLeftCorner<3, 3>() * est[i] + t.topRightCorner<3, 1>();
    const double e = (aligned - gt[i]).norm();
    sum_sq += e * e;
    out.max_m = std::max(out.max_m, e);
  }
  out.rmse_m = std::sqrt(sum_sq / static_cast<double>(est.size()));
  return out;
}

}  // namespace wifislam::test
