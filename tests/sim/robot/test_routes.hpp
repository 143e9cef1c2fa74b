#pragma once
// Hand-built robot routes (dense RoutePaths) for tests that must not depend on the world
// generator: a straight line, a circle, a rectangle with rounded corners, and a corridor walked
// down and back with a turn on the spot at its end.

#include <cmath>
#include <numbers>

#include "sim/world/world_types.hpp"

namespace wifislam::test {

inline void append_point(sim::world::RoutePath& path, const Eigen::Vector2d& p,
                         double heading_rad) {
  path.arc_length_m.push_back(
      path.points_m.empty() ? 0.0 : path.arc_length_m.back() + (p - path.points_m.back()).norm());
  path.points_m.push_back(p);
  path.heading_rad.push_back(std::remainder(heading_rad, 2.0 * std::numbers::pi));
}

/// Straight along +x from the origin, points every `step_m`.
inline sim::world::RoutePath straight_route(double length_m, double step_m = 0.05) {
  sim::world::RoutePath path;
  const int n = static_cast<int>(std::round(length_m / step_m));
  for (int i = 0; i <= n; ++i) append_point(path, {i * step_m, 0.0}, 0.0);
  return path;
}

/// Counter-clockwise circle of `radius_m` around the origin, `laps` times.
inline sim::world::RoutePath circle_route(double radius_m, double laps, double step_m = 0.05) {
  sim::world::RoutePath path;
  const double total_rad = laps * 2.0 * std::numbers::pi;
  const int n = static_cast<int>(std::round(total_rad * radius_m / step_m));
  for (int i = 0; i <= n; ++i) {
    const double a = total_rad * i / n;
    append_point(path, {radius_m * std::cos(a), radius_m * std::sin(a)}, a + std::numbers::pi / 2);
  }
  return path;
}

/// A w x h rectangle (counter-clockwise from the origin) with corners rounded by `radius_m`.
inline sim::world::RoutePath rounded_rectangle_route(double w_m, double h_m, double radius_m,
                                                     double step_m = 0.05) {
  sim::world::RoutePath path;
  const Eigen::Vector2d corners[4] = {{w_m, 0}, {w_m, h_m}, {0, h_m}, {0, 0}};
  Eigen::Vector2d at(radius_m, 0.0);
  double heading = 0.0;
  append_point(path, at, heading);
  for (int c = 0; c < 4; ++c) {
    const Eigen::Vector2d dir(std::cos(heading), std::sin(heading));
    const Eigen::Vector2d straight_end = corners[c] - radius_m * dir;
    const double len = (straight_end - at).norm();
    const int n = std::max(1, static_cast<int>(std::round(len / step_m)));
    for (int i = 1; i <= n; ++i) append_point(path, at + (straight_end - at) * i / n, heading);
    const Eigen::Vector2d left(-dir.y(), dir.x());
    const Eigen::Vector2d centre = straight_end + radius_m * left;
    const int m =
        std::max(2, static_cast<int>(std::round(radius_m * std::numbers::pi / 2 / step_m)));
    for (int i = 1; i <= m; ++i) {
      const double a = heading - std::numbers::pi / 2 + (std::numbers::pi / 2) * i / m;
      append_point(path, centre + radius_m * Eigen::Vector2d(std::cos(a), std::sin(a)),
                   heading + (std::numbers::pi / 2) * i / m);
    }
    heading += std::numbers::pi / 2;
    at = path.points_m.back();
  }
  return path;
}

/// Along +x for `length_m`, a half turn on the spot (to the left, in steps of at most 0.05 rad, as
/// the route builder turns at a dead end), and back to the origin.
inline sim::world::RoutePath there_and_back_route(double length_m, double step_m = 0.05) {
  sim::world::RoutePath path = straight_route(length_m, step_m);
  const Eigen::Vector2d end = path.points_m.back();
  const int turn_steps = static_cast<int>(std::ceil(std::numbers::pi / 0.05));
  for (int k = 1; k <= turn_steps; ++k) append_point(path, end, std::numbers::pi * k / turn_steps);
  const int n = static_cast<int>(std::round(length_m / step_m));
  for (int i = n - 1; i >= 0; --i) append_point(path, {i * step_m, 0.0}, std::numbers::pi);
  return path;
}

}  // namespace wifislam::test
