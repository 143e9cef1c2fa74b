#include "tests/slam/trajectory_error.hpp"

#include <algorithm>
#include <cmath>

#include "eval/alignment.hpp"

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
  const eval::Alignment alignment = eval::align_points(a, b, /*with_scale=*/false);
  double sum_sq = 0.0;
  for (std::size_t i = 0; i < est.size(); ++i) {
    const double e = (alignment.apply(est[i]) - gt[i]).norm();
    sum_sq += e * e;
    out.max_m = std::max(out.max_m, e);
  }
  out.rmse_m = std::sqrt(sum_sq / static_cast<double>(est.size()));
  return out;
}

}  // namespace wifislam::test
