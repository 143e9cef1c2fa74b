#include "sim/robot/motion_profile.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/rng.hpp"

namespace wifislam::sim::robot {

namespace {

double wrap_angle(double a) {
  a = std::remainder(a, 2.0 * std::numbers::pi);
  return a <= -std::numbers::pi ? a + 2.0 * std::numbers::pi : a;
}

// Knot times are whole microseconds so that pause boundaries (and the scans scheduled in them)
// print exactly with the 6 decimals of TUM files.
std::int64_t to_knot_ns(double t_s) { return std::llround(t_s * 1e6) * 1000; }

}  // namespace

RobotMotionOptions RobotMotionOptions::from_route(const scene::Route& route) {
  RobotMotionOptions o;
  o.speed_mps = route.speed_mps;
  o.max_yaw_rate_radps = route.max_yaw_rate_radps;
  o.pause = route.pause;
  return o;
}

Pose RobotState::base_to_world() const {
  Pose pose = Pose::Identity();
  pose.linear() = Eigen::AngleAxisd(heading_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(position_m.x(), position_m.y(), 0.0);
  return pose;
}

MotionProfile::MotionProfile(const world::RoutePath& path, const RobotMotionOptions& options,
                             std::uint64_t seed)
    : path_(path), options_(options) {
  const std::size_t n = path_.points_m.size();
  if (n < 2 || path_.arc_length_m.size() != n || path_.heading_rad.size() != n) {
    throw InvalidInputError("robot route: needs at least two points with arc length and heading");
  }
  // Progress: arc length plus the radians turned on the spot so far (a dead end the robot goes
  // back from), so that every part of the route takes time. On a route without such turns it is
  // the arc length itself, bit for bit, and the robot's poses are those of arc-length timing.
  turned_rad_.push_back(0.0);
  progress_.push_back(path_.arc_length_m.front());
  for (std::size_t i = 1; i < n; ++i) {
    const double ds = path_.arc_length_m[i] - path_.arc_length_m[i - 1];
    if (!(ds >= 0.0)) {
      throw InvalidInputError("robot route: arc length decreases at point " + std::to_string(i));
    }
    const double turn_rad = std::abs(wrap_angle(path_.heading_rad[i] - path_.heading_rad[i - 1]));
    turned_rad_.push_back(turned_rad_.back() + (ds > 0.0 ? 0.0 : turn_rad));
    progress_.push_back(path_.arc_length_m[i] + turned_rad_.back());
  }
  if (!(progress_.back() > progress_.front())) {
    throw InvalidInputError("robot route: the route neither moves nor turns");
  }
  if (!(options_.speed_mps > 0.0) || !(options_.max_yaw_rate_radps > 0.0)) {
    throw InvalidInputError("robot: speed_mps and max_yaw_rate_radps must be positive");
  }
  const scene::PauseSpec& pause = options_.pause;
  if (!(pause.spacing_min_m > 0.0) || pause.spacing_max_m < pause.spacing_min_m ||
      pause.duration_s < 0.0) {
    throw InvalidInputError(
        "robot: pause spacing must be a positive range [min, max] and duration_s >= 0");
  }

  // Where the robot pauses (arc lengths), drawn before any timing so that the spacing does not
  // depend on the speed profile.
  std::vector<double> pause_s;
  if (options_.pause_at_start) pause_s.push_back(0.0);
  Rng rng = Rng::stream(seed, "robot/pauses");
  for (double s = 0.0;;) {
    s += rng.uniform(pause.spacing_min_m, pause.spacing_max_m);
    if (s > path_.length_m()) break;
    pause_s.push_back(s);
  }

  double t_s = 0.0;
  double s_now = path_.arc_length_m.front();
  double u_now = progress_.front();
  knot_ns_.push_back(0);
  knot_u_.push_back(u_now);
  std::size_t next_pause = 0;
  auto add_knot = [&](double u, int pause_index_of_previous_interval) {
    knot_pause_.push_back(pause_index_of_previous_interval);
    knot_ns_.push_back(to_knot_ns(t_s));
    knot_u_.push_back(u);
  };
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double s0 = path_.arc_length_m[i], s1 = path_.arc_length_m[i + 1];
    const double turn_rad = std::abs(wrap_angle(path_.heading_rad[i + 1] - path_.heading_rad[i]));
    if (s1 == s0) {
      // Turning on the spot at the yaw-rate limit; pauses fall before or after, never inside.
      if (turn_rad > 0.0) {
        t_s += turn_rad / options_.max_yaw_rate_radps;
        u_now = progress_[i + 1];
        add_knot(u_now, -1);
      }
      continue;
    }
    double v = options_.speed_mps;
    if (turn_rad > 0.0) v = std::min(v, options_.max_yaw_rate_radps * (s1 - s0) / turn_rad);
    const bool last = i + 2 == n;
    while (next_pause < pause_s.size() &&
           (pause_s[next_pause] < s1 || (last && pause_s[next_pause] <= s1))) {
      const double sp = std::max(pause_s[next_pause], s_now);
      if (sp > s_now) {
        t_s += (sp - s_now) / v;
        u_now = sp + turned_rad_[i];
        add_knot(u_now, -1);
        s_now = sp;
      }
      RobotPause p;
      p.arc_length_m = sp;
      p.position_m = position_at_arc_length(sp);
      p.start = Timestamp::from_ns(knot_ns_.back());
      t_s += pause.duration_s;
      add_knot(u_now, static_cast<int>(pauses_.size()));
      p.end = Timestamp::from_ns(knot_ns_.back());
      pauses_.push_back(p);
      ++next_pause;
    }
    if (s1 > s_now) {
      t_s += (s1 - s_now) / v;
      s_now = s1;
      u_now = progress_[i + 1];
      add_knot(u_now, -1);
    }
  }
  knot_pause_.push_back(-1);  // after the last knot: standing at the end
}

std::size_t MotionProfile::path_segment(double s_m) const {
  const auto& arc = path_.arc_length_m;
  auto it = std::upper_bound(arc.begin(), arc.end(), s_m);
  std::size_t i = it == arc.begin() ? 0 : static_cast<std::size_t>(it - arc.begin()) - 1;
  return std::min(i, arc.size() - 2);
}

std::size_t MotionProfile::progress_segment(double u) const {
  auto it = std::upper_bound(progress_.begin(), progress_.end(), u);
  std::size_t i =
      it == progress_.begin() ? 0 : static_cast<std::size_t>(it - progress_.begin()) - 1;
  return std::min(i, progress_.size() - 2);
}

Eigen::Vector2d MotionProfile::position_at_arc_length(double s_m) const {
  const std::size_t i = path_segment(s_m);
  const double s0 = path_.arc_length_m[i], s1 = path_.arc_length_m[i + 1];
  const double f = s1 > s0 ? std::clamp((s_m - s0) / (s1 - s0), 0.0, 1.0) : 1.0;
  return path_.points_m[i] + f * (path_.points_m[i + 1] - path_.points_m[i]);
}

double MotionProfile::heading_at_arc_length(double s_m) const {
  const std::size_t i = path_segment(s_m);
  const double s0 = path_.arc_length_m[i], s1 = path_.arc_length_m[i + 1];
  const double f = s1 > s0 ? std::clamp((s_m - s0) / (s1 - s0), 0.0, 1.0) : 1.0;
  const double dh = wrap_angle(path_.heading_rad[i + 1] - path_.heading_rad[i]);
  return wrap_angle(path_.heading_rad[i] + f * dh);
}

RobotState MotionProfile::state_at(Timestamp t) const {
  const std::int64_t ns = std::clamp<std::int64_t>(t.ns, 0, knot_ns_.back());
  auto it = std::upper_bound(knot_ns_.begin(), knot_ns_.end(), ns);
  std::size_t k = static_cast<std::size_t>(it - knot_ns_.begin()) - 1;
  RobotState state;
  double u = knot_u_[k];
  double rate = 0.0;  // progress per second
  if (k + 1 < knot_ns_.size()) {
    const std::int64_t dt = knot_ns_[k + 1] - knot_ns_[k];
    const double du = knot_u_[k + 1] - knot_u_[k];
    if (knot_pause_[k] >= 0) {
      state.pause_index = knot_pause_[k];
    } else if (dt > 0) {
      u += du * static_cast<double>(ns - knot_ns_[k]) / static_cast<double>(dt);
      rate = du / (static_cast<double>(dt) * 1e-9);
    }
  }
  // The route segment holding u; at its far end (or a knot) the next one, as upper_bound gives.
  const std::size_t i = progress_segment(u);
  const double s0 = path_.arc_length_m[i], s1 = path_.arc_length_m[i + 1];
  const double dh = wrap_angle(path_.heading_rad[i + 1] - path_.heading_rad[i]);
  double f = 1.0;
  if (s1 > s0) {
    // Moving: arc length as arc-length timing gives it (turned_rad_ is 0 on routes without turns
    // on the spot), then the same interpolation as position_at_arc_length.
    state.arc_length_m = u - turned_rad_[i];
    f = std::clamp((state.arc_length_m - s0) / (s1 - s0), 0.0, 1.0);
  } else {
    state.arc_length_m = s0;
    const double u0 = progress_[i], u1 = progress_[i + 1];
    if (u1 > u0) f = std::clamp((u - u0) / (u1 - u0), 0.0, 1.0);
  }
  state.position_m = path_.points_m[i] + f * (path_.points_m[i + 1] - path_.points_m[i]);
  state.heading_rad = wrap_angle(path_.heading_rad[i] + f * dh);
  if (rate > 0.0) {
    if (s1 > s0) {
      state.speed_mps = rate;
      state.velocity_mps = rate * (path_.points_m[i + 1] - path_.points_m[i]) / (s1 - s0);
      state.yaw_rate_radps = rate * dh / (s1 - s0);
    } else if (dh != 0.0) {
      state.yaw_rate_radps = dh > 0.0 ? rate : -rate;
    }
  }
  return state;
}

double MotionProfile::moving_time_s() const {
  std::int64_t paused_ns = 0;
  for (const RobotPause& p : pauses_) paused_ns += p.end.ns - p.start.ns;
  return static_cast<double>(knot_ns_.back() - paused_ns) * 1e-9;
}

}  // namespace wifislam::sim::robot
