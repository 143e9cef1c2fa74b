#pragma once
// Where the robot is at any time: a motion profile along the route (RoutePath), precomputed once
// as a list of knots (time, arc length) with constant speed between consecutive knots. The pose at
// time t is then a pure function of t (binary search + interpolation), never the result of
// integrating velocities, so ground truth is exact and frames can be produced in any order.
//
// Speed: `speed_mps` on straight parts; in turns the robot slows down so that its yaw rate never
// exceeds `max_yaw_rate_radps` (the route's corners are already rounded by the world generator,
// so slowing down is enough for smooth turns). Between two route points the speed is constant and
// the heading changes linearly with time, so the bound holds exactly, not just at the points.
// Where the route turns on the spot (points at one arc length with changing heading: a dead end
// the robot goes back from), the robot stands and turns at exactly `max_yaw_rate_radps`.
//
// Pauses (paper, "Wi-Fi data processing": the robot stands still ~10 s every few metres to scan):
// one at the start of the route, then one after every spacing drawn uniformly from
// [spacing_min_m, spacing_max_m] with the sub-stream "robot/pauses" of the seed, as long as the
// pause point lies on the route. During a pause the robot does not move at all.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/pose.hpp"
#include "core/timestamp.hpp"
#include "sim/scene/scene.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::robot {

struct RobotMotionOptions {
  double speed_mps = 0.5;           // cruise speed (TurtleBot 2 default driving speed)
  double max_yaw_rate_radps = 0.6;  // turns slow the robot down to stay below this
  scene::PauseSpec pause;           // spacing range, duration, scanning while moving
  bool pause_at_start = true;       // stand and scan before moving (the first frames get a
                                    // signature of their own place)
  static RobotMotionOptions from_route(const scene::Route& route);
};

/// One pause: the robot stands at `arc_length_m` during [start, end) (whole microseconds).
struct RobotPause {
  double arc_length_m = 0.0;
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();
  Timestamp start, end;
};

/// The robot base at one instant. The base frame: x forward, y left, z up, on the floor.
struct RobotState {
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();
  double heading_rad = 0.0;   // direction of travel, counter-clockwise from +x, in (-pi, pi]
  double arc_length_m = 0.0;  // distance travelled along the route
  double speed_mps = 0.0;     // 0 during pauses
  // The base's velocity in the world: along the route segment it is on (route points are close
  // together, so the base follows the chords while its heading turns smoothly).
  Eigen::Vector2d velocity_mps = Eigen::Vector2d::Zero();
  double yaw_rate_radps = 0.0;  // signed
  int pause_index = -1;         // the pause the robot is in, else -1

  bool paused() const { return pause_index >= 0; }
  /// Base-to-world pose (z = 0).
  Pose base_to_world() const;
};

class MotionProfile {
 public:
  /// Throws InvalidInputError for a route with fewer than two points, decreasing arc length, or
  /// neither length nor turn.
  MotionProfile(const world::RoutePath& path, const RobotMotionOptions& options,
                std::uint64_t seed);

  /// The state at time t; times before 0 give the start, after end_time() the end.
  RobotState state_at(Timestamp t) const;
  /// Position on the route at arc length s (clamped to the route).
  Eigen::Vector2d position_at_arc_length(double s_m) const;
  double heading_at_arc_length(double s_m) const;

  /// When the robot reaches the end of the route (whole microseconds).
  Timestamp end_time() const { return Timestamp::from_ns(knot_ns_.back()); }
  double length_m() const { return path_.length_m(); }
  const std::vector<RobotPause>& pauses() const { return pauses_; }
  const RobotMotionOptions& options() const { return options_; }
  /// Time spent moving (end time minus pauses), seconds.
  double moving_time_s() const;

 private:
  // Index i such that arc_length_m[i] <= s < arc_length_m[i + 1] (clamped).
  std::size_t path_segment(double s_m) const;
  // The same for progress u (progress_[i] <= u < progress_[i + 1], clamped).
  std::size_t progress_segment(double u) const;

  world::RoutePath path_;
  RobotMotionOptions options_;
  // Progress along the route at each route point: arc length plus the radians turned on the spot
  // up to it (turned_rad_); strictly increases wherever the robot moves or turns.
  std::vector<double> progress_;
  std::vector<double> turned_rad_;
  std::vector<std::int64_t> knot_ns_;  // non-decreasing
  std::vector<double> knot_u_;         // progress at each knot (non-decreasing)
  std::vector<int> knot_pause_;        // pause index of the interval [knot i, knot i+1], else -1
  std::vector<RobotPause> pauses_;
};

}  // namespace wifislam::sim::robot
