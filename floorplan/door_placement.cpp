#include "floorplan/door_placement.hpp"

#include <algorithm>
#include <cmath>

namespace wifislam::floorplan {

DoorShape door_shape(const Ring& ring) {
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const auto& p : ring) c += p;
  c /= static_cast<double>(ring.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const auto& p : ring) cov += (p - c) * (p - c).transpose();
  const double angle = 0.5 * std::atan2(2 * cov(0, 1), cov(0, 0) - cov(1, 1));
  const Eigen::Vector2d axis(std::cos(angle), std::sin(angle));
  double lo = 1e300, hi = -1e300;
  for (const auto& p : ring)
    lo = std::min(lo, (p - c).dot(axis)), hi = std::max(hi, (p - c).dot(axis));
  return {c + 0.5 * (lo + hi) * axis, axis, hi - lo};
}

DoorShape opening_shape(const Ring& line) {
  const Eigen::Vector2d d = line.back() - line.front();
  return {0.5 * (line.front() + line.back()), d.normalized(), d.norm()};
}

std::optional<PlacedDoor> door_on_shared_wall(const DoorShape& shape, const Partition& partition,
                                              bool open) {
  const SharedWall* best = nullptr;
  double best_d = 0.6;
  for (const SharedWall& w : partition.shared_walls) {
    const Eigen::Vector2d d = (w.to_m - w.from_m).normalized();
    if (std::abs(d.dot(shape.axis)) < 0.9) continue;
    const double s = std::clamp((shape.centre - w.from_m).dot(d), 0.0, w.length_m());
    const double dist = (w.from_m + s * d - shape.centre).norm();
    if (dist < best_d) best_d = dist, best = &w;
  }
  if (best == nullptr || best->length_m() < 0.6) return std::nullopt;
  const Eigen::Vector2d d = (best->to_m - best->from_m).normalized();
  const double width = std::clamp(shape.length_m, 0.6, std::min(3.0, best->length_m()));
  const double s =
      std::clamp((shape.centre - best->from_m).dot(d), 0.5 * width, best->length_m() - 0.5 * width);
  PlacedDoor door;
  door.a = best->a;
  door.b = best->b;
  door.door.from_m = best->from_m + (s - 0.5 * width) * d;
  door.door.to_m = best->from_m + (s + 0.5 * width) * d;
  door.door.open = open;
  return door;
}

}  // namespace wifislam::floorplan
