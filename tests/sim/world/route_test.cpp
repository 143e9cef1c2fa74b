#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "sim/world/floor_plan_builder.hpp"
#include "sim/world/route_builder.hpp"
#include "sim/world/world_generator.hpp"
#include "tests/sim/world/world_test_support.hpp"

namespace wifislam::sim {
namespace {

TEST(Route, CornersAreRoundedWithTheTurnRadius) {
  const scene::Scene scene = test::square_loop_scene(14.0);
  const world::FloorPlan plan = world::build_floor_plan(scene);
  const world::RoutePath route = world::build_route(scene, plan);
  const double r = scene.route.turn_radius_m;
  // The corners at B, C and D (not the start/end node A) replace 2r of straight line each with a
  // quarter circle (sampled by chords, hence the tolerance).
  EXPECT_NEAR(route.length_m(), 4 * 14.0 - 3 * (2 * r - M_PI / 2 * r), 2e-3);
  // The arc passes r (sqrt 2 - 1) from the corner node.
  double closest = std::numeric_limits<double>::infinity();
  for (const auto& p : route.points_m)
    closest = std::min(closest, (p - Eigen::Vector2d(14, 0)).norm());
  EXPECT_NEAR(closest, r * (std::sqrt(2.0) - 1), 0.01);
  // Heading changes smoothly: never more than one sample's worth of arc.
  for (std::size_t k = 1; k < route.heading_rad.size(); ++k) {
    const double dh = std::remainder(route.heading_rad[k] - route.heading_rad[k - 1], 2 * M_PI);
    EXPECT_LE(std::abs(dh), 0.05 / r + 1e-9);
  }
  // A loop starts and ends at its first node, unsmoothed.
  EXPECT_EQ(route.points_m.front(), Eigen::Vector2d(0, 0));
  EXPECT_EQ(route.points_m.back(), Eigen::Vector2d(0, 0));
}

TEST(Route, DeadEndTurnsOnTheSpot) {
  scene::Scene scene = test::square_loop_scene(14.0);
  scene.route.nodes = {"A", "B", "A"};
  const world::FloorPlan plan = world::build_floor_plan(scene);
  const world::RoutePath route = world::build_route(scene, plan);
  EXPECT_NEAR(route.length_m(), 28.0, 1e-9);
  int at_b = 0;
  for (const auto& p : route.points_m) at_b += (p - Eigen::Vector2d(14, 0)).norm() < 1e-12;
  EXPECT_GT(at_b, 10) << "the turn at B is a rotation in place";
}

TEST(Route, RouteThatCannotKeepClearanceIsRejected) {
  scene::Scene scene =
      test::square_loop_scene(14.0, 0.5);  // 0.25 m from the centre line to the walls
  try {
    world::generate_world(scene);
    FAIL() << "expected InvalidInputError";
  } catch (const InvalidInputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("route leg 0"), std::string::npos) << msg;
    EXPECT_NE(msg.find("min_wall_clearance_m"), std::string::npos) << msg;
  }
}

TEST(Route, RouteBetweenNodesWithoutCorridorIsRejected) {
  scene::Scene scene = test::square_loop_scene(14.0);
  scene.route.nodes = {"A", "B", "D"};
  try {
    world::generate_world(scene);
    FAIL() << "expected InvalidInputError";
  } catch (const InvalidInputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("'B' and 'D'"), std::string::npos) << msg;
  }
}

}  // namespace
}  // namespace wifislam::sim
