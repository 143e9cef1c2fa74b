#include "sim/world/route_builder.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "core/error.hpp"
#include "sim/world/plan_queries.hpp"
#include "sim/world/region_locator.hpp"
#include "sim/world/wall_face_grid.hpp"

namespace wifislam::sim::world {

namespace {

constexpr double kMaxSpacingM = 0.05;
constexpr double kMaxTurnStepRad = 0.05;  // heading step while turning on the spot

struct Sampler {
  RoutePath path;
  std::vector<int> leg;  // route leg of each sample, for error messages

  void push(const Eigen::Vector2d& p, double heading, int leg_index) {
    const double s =
        path.points_m.empty() ? 0.0 : path.arc_length_m.back() + (p - path.points_m.back()).norm();
    path.points_m.push_back(p);
    path.arc_length_m.push_back(s);
    path.heading_rad.push_back(heading);
    leg.push_back(leg_index);
  }

  /// Straight line from the last point to `to` (excluding the start, including `to`).
  void line_to(const Eigen::Vector2d& to, int leg_index) {
    const Eigen::Vector2d from = path.points_m.back();
    const double length = (to - from).norm();
    if (length < 1e-12) return;
    const double heading = std::atan2(to.y() - from.y(), to.x() - from.x());
    const int n = std::max(1, static_cast<int>(std::ceil(length / kMaxSpacingM)));
    for (int k = 1; k <= n; ++k) push(from + (to - from) * (double(k) / n), heading, leg_index);
  }

  /// Arc around `center` from the last point, turning by `turn_rad` (positive = left).
  void arc(const Eigen::Vector2d& center, double turn_rad, int leg_index) {
    const Eigen::Vector2d r0 = path.points_m.back() - center;
    const double radius = r0.norm(), start = std::atan2(r0.y(), r0.x());
    const int n =
        std::max(1, static_cast<int>(std::ceil(std::abs(turn_rad) * radius / kMaxSpacingM)));
    const double side = turn_rad > 0 ? 1.0 : -1.0;
    for (int k = 1; k <= n; ++k) {
      const double a = start + turn_rad * k / n;
      push(center + radius * Eigen::Vector2d(std::cos(a), std::sin(a)), a + side * M_PI / 2,
           leg_index);
    }
  }

  /// Turn on the spot by `turn_rad`.
  void rotate(double turn_rad, int leg_index) {
    const Eigen::Vector2d p = path.points_m.back();
    const double start = path.heading_rad.back();
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(turn_rad) / kMaxTurnStepRad)));
    for (int k = 1; k <= n; ++k) push(p, start + turn_rad * k / n, leg_index);
  }
};

double wrap_angle(double a) { return std::atan2(std::sin(a), std::cos(a)); }

/// The route's corner points: its nodes' positions, or its waypoints.
std::vector<Eigen::Vector2d> route_points(const scene::Scene& scene) {
  const scene::Route& route = scene.route;
  if (!route.waypoints_m.empty()) {
    if (route.waypoints_m.size() < 2)
      throw InvalidInputError("route.waypoints_m: a route needs at least two waypoints");
    for (std::size_t i = 1; i < route.waypoints_m.size(); ++i)
      if ((route.waypoints_m[i] - route.waypoints_m[i - 1]).norm() < 1e-6)
        scene.reject(fmt::format("route.waypoints_m[{}]", i),
                     "the same point as the waypoint before it");
    return route.waypoints_m;
  }
  if (route.nodes.size() < 2)
    throw InvalidInputError("route.nodes: a route needs at least two nodes");
  std::vector<Eigen::Vector2d> pts;
  for (std::size_t i = 0; i < route.nodes.size(); ++i) {
    const scene::SceneNode* node = scene.find_node(route.nodes[i]);
    if (node == nullptr)
      throw InvalidInputError(
          fmt::format("route.nodes[{}]: node '{}' does not exist", i, route.nodes[i]));
    if (i > 0 && scene.corridor_between(route.nodes[i - 1], route.nodes[i]) == nullptr)
      scene.reject(
          fmt::format("route.nodes[{}]", i),
          fmt::format("no corridor joins nodes '{}' and '{}'", route.nodes[i - 1], route.nodes[i]));
    pts.push_back(node->position_m);
  }
  return pts;
}

}  // namespace

RoutePath build_route(const scene::Scene& scene, const FloorPlan& plan) {
  const scene::Route& route = scene.route;
  const std::vector<Eigen::Vector2d> pts = route_points(scene);
  const bool by_waypoints = !route.waypoints_m.empty();

  // Corner geometry: tangent points and arcs, shrunk so two corners never share a leg's length.
  const std::size_t n = pts.size();
  std::vector<double> tangent(n, 0.0), turn(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const Eigen::Vector2d d_in = (pts[i] - pts[i - 1]).normalized();
    const Eigen::Vector2d d_out = (pts[i + 1] - pts[i]).normalized();
    turn[i] = std::atan2(d_in.x() * d_out.y() - d_in.y() * d_out.x(), d_in.dot(d_out));
    if (std::abs(turn[i]) < 1e-9) continue;
    if (std::abs(turn[i]) > M_PI - 1e-6) {
      turn[i] = M_PI;  // dead end: turn on the spot, to the left
      continue;
    }
    const double half_leg =
        0.5 * std::min((pts[i] - pts[i - 1]).norm(), (pts[i + 1] - pts[i]).norm());
    tangent[i] = std::min(route.turn_radius_m * std::tan(0.5 * std::abs(turn[i])), half_leg);
  }

  Sampler sampler;
  const Eigen::Vector2d first_dir = pts[1] - pts[0];
  sampler.push(pts[0], std::atan2(first_dir.y(), first_dir.x()), 0);
  for (std::size_t i = 1; i < n; ++i) {
    const int leg = static_cast<int>(i - 1);
    const Eigen::Vector2d d_in = (pts[i] - pts[i - 1]).normalized();
    if (i + 1 == n || std::abs(turn[i]) < 1e-9) {
      sampler.line_to(pts[i], leg);
      continue;
    }
    if (tangent[i] == 0.0) {
      sampler.line_to(pts[i], leg);
      sampler.rotate(turn[i], leg);
      continue;
    }
    const double radius = tangent[i] / std::tan(0.5 * std::abs(turn[i]));
    const Eigen::Vector2d left(-d_in.y(), d_in.x());
    const double side = turn[i] > 0 ? 1.0 : -1.0;
    const Eigen::Vector2d entry = pts[i] - tangent[i] * d_in;
    sampler.line_to(entry, leg);
    sampler.arc(entry + side * radius * left, turn[i], leg);
  }
  for (double& h : sampler.path.heading_rad) h = wrap_angle(h);

  // Clearance and walkability of every sample.
  const double clearance = route.min_wall_clearance_m;
  std::optional<WallFaceGrid> walls;
  if (clearance > 0.0) walls.emplace(plan, clearance);
  const RegionLocator walkable(plan.walkable);  // ~20 samples a metre: not every edge per sample
  for (std::size_t k = 0; k < sampler.path.points_m.size(); ++k) {
    const Eigen::Vector2d& p = sampler.path.points_m[k];
    const int leg = sampler.leg[k];
    const auto where = [&] {  // formatted only for an error: routes have ~20 samples a metre
      if (by_waypoints)
        return fmt::format("route leg {} (from waypoint {} to {}), point {} at ({:.2f}, {:.2f}) m",
                           leg, leg, leg + 1, k, p.x(), p.y());
      return fmt::format("route leg {} (from node '{}' to '{}'), point {} at ({:.2f}, {:.2f}) m",
                         leg, route.nodes[leg], route.nodes[leg + 1], k, p.x(), p.y());
    };
    // Located at the node (waypoint) the leg leads to.
    const auto key = [&] {
      return by_waypoints ? fmt::format("route.waypoints_m[{}]", leg + 1)
                          : fmt::format("route.nodes[{}]", leg + 1);
    };
    if (walkable.find(p) < 0)
      scene.reject(key(), where() + ": outside the corridors, open areas and walkable spaces");
    if (!walls) continue;
    const double d = walls->nearest_within_m(p, clearance);
    if (d < clearance - 1e-9)
      scene.reject(
          key(),
          fmt::format("{}: only {:.3f} m from a wall, route.min_wall_clearance_m is {:.3f} m",
                      where(), d, clearance));
  }
  return sampler.path;
}

}  // namespace wifislam::sim::world
