// An obstacle that cuts a thin strip off a space gives the strip to the obstacle; one that cuts
// a space in two large halves changes nothing (the world builder judges the halves).
#include <gtest/gtest.h>

#include <vector>

#include "floorplan/geos_geometry.hpp"
#include "floorplan/obstacle_strips.hpp"
#include "floorplan/space_partition.hpp"

namespace wifislam {
namespace {

using floorplan::Ring;

Ring rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

/// One 10 x 10 m piece and a 40 x 10 m one, far apart.
floorplan::Partition two_pieces() {
  floorplan::Partition partition;
  partition.pieces.push_back({0, {rectangle(0, 0, 10, 10), {}}});
  partition.pieces.push_back({1, {rectangle(20, 0, 60, 10), {}}});
  return partition;
}

double area_m2(const floorplan::GeosContext& geos, const Ring& ring) {
  return geos.polygon({ring, {}}).area_m2();
}

constexpr double kMinAreaM2 = 0.5, kWallM = 0.3;

TEST(ObstacleStrips, AStripCutOffBetweenAnObstacleAndTheWallBecomesPartOfTheObstacle) {
  const floorplan::GeosContext geos;
  // A wall island across the small piece, 2 cm from its north wall and through both side walls;
  // another inside the piece, touching nothing.
  std::vector<sim::scene::Obstacle> obstacles = {{rectangle(-0.5, 9.5, 10.5, 9.98), {}},
                                                 {rectangle(4, 4, 5, 5), {}}};
  EXPECT_EQ(floorplan::make_cut_off_strips_solid(geos, two_pieces(), kMinAreaM2, kWallM, obstacles),
            1);
  // The island now reaches the wall: nothing of the piece north of it is free.
  const floorplan::Geometry free = geos.polygon({rectangle(0, 0, 10, 10), {}})
                                       .minus(geos.polygon({obstacles[0].polygon_m, {}}))
                                       .polygonal();
  ASSERT_EQ(free.polygons().size(), 1u);
  EXPECT_NEAR(free.area_m2(), 10 * 9.5, 0.01);
  // It grew by the strip (11 x 0.48 m + 10 x 0.02 m) and the overlap that keeps exact arithmetic
  // from leaving a hair of free space, and no more.
  EXPECT_NEAR(area_m2(geos, obstacles[0].polygon_m), 11 * 0.48 + 10 * 0.02, 0.05);
  EXPECT_EQ(obstacles[1].polygon_m, rectangle(4, 4, 5, 5)) << "an obstacle inside is left alone";
}

// A strip as long as a corridor has the area of a room (2 cm x 40 m = 0.8 m^2): narrower than a
// wall, it is a strip all the same.
TEST(ObstacleStrips, ALongStripNarrowerThanAWallIsAStripWhateverItsArea) {
  const floorplan::GeosContext geos;
  std::vector<sim::scene::Obstacle> obstacles = {{rectangle(19.5, 9.5, 60.5, 9.98), {}}};
  EXPECT_EQ(floorplan::make_cut_off_strips_solid(geos, two_pieces(), kMinAreaM2, kWallM, obstacles),
            1);
  const floorplan::Geometry free = geos.polygon({rectangle(20, 0, 60, 10), {}})
                                       .minus(geos.polygon({obstacles[0].polygon_m, {}}))
                                       .polygonal();
  EXPECT_EQ(free.polygons().size(), 1u);
}

TEST(ObstacleStrips, AnObstacleThatCutsASpaceInTwoHalvesIsLeftAlone) {
  const floorplan::GeosContext geos;
  std::vector<sim::scene::Obstacle> obstacles = {{rectangle(-0.5, 4.8, 10.5, 5.2), {}}};
  const std::vector<sim::scene::Obstacle> before = obstacles;
  EXPECT_EQ(floorplan::make_cut_off_strips_solid(geos, two_pieces(), kMinAreaM2, kWallM, obstacles),
            0);
  EXPECT_EQ(obstacles[0].polygon_m, before[0].polygon_m);
}

TEST(ObstacleStrips, AnInvalidObstacleIsLeftForTheWorldBuilderToName) {
  const floorplan::GeosContext geos;
  // A bow tie across the north wall: not a polygon GEOS can subtract.
  std::vector<sim::scene::Obstacle> obstacles = {
      {{{-0.5, 9.5}, {10.5, 9.98}, {10.5, 9.5}, {-0.5, 9.98}}, {}}};
  const std::vector<sim::scene::Obstacle> before = obstacles;
  EXPECT_EQ(floorplan::make_cut_off_strips_solid(geos, two_pieces(), kMinAreaM2, kWallM, obstacles),
            0);
  EXPECT_EQ(obstacles[0].polygon_m, before[0].polygon_m);
}

}  // namespace
}  // namespace wifislam
