#pragma once
// The world's walls in Embree 3, for the question the radio model asks millions of times: which
// physical walls does the straight segment from an access point to a receiver cross?
//
// Built from every mesh triangle with a wall_id >= 0 (wall faces, closed door leaves, jambs;
// floors, ceilings and posters carry -1). A thick wall is a closed solid whose faces share one
// wall_id, so a segment through it hits two faces but crosses one wall: crossings are merged per
// wall_id (this also merges the two hits reported where a segment passes exactly through an edge
// shared by two triangles). An open door is a gap in the mesh, so a segment through it crosses
// nothing there. One wall_id per convex wall piece is assumed: a segment cannot cross the same
// convex solid twice.
//
// Two Embree scenes share the device: one with an intersection filter that records every hit
// and rejects it so traversal continues (one traversal per segment, no restarts), one without
// filter for plain first-hit rays (an attached filter slows every query on its scene).
// Queries are const and thread-safe.

#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "sim/world/world_types.hpp"

namespace wifislam {

struct WallCrossing {
  int wall_id = -1;
  WallMaterial material = WallMaterial::kPlasterboard;
  double distance_m = 0.0;  // from the segment's start to the first face of this wall
};

class EmbreeWallScene {
 public:
  /// Throws EnvironmentError if Embree cannot create a device or scene.
  explicit EmbreeWallScene(const Mesh& mesh);
  ~EmbreeWallScene();
  EmbreeWallScene(const EmbreeWallScene&) = delete;
  EmbreeWallScene& operator=(const EmbreeWallScene&) = delete;

  /// Distinct walls crossed strictly between `from` and `to`, sorted by distance. `out` is
  /// cleared first; passing the same vector again avoids allocations.
  void walls_crossed(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                     std::vector<WallCrossing>& out) const;
  std::vector<WallCrossing> walls_crossed(const Eigen::Vector3d& from,
                                          const Eigen::Vector3d& to) const;

  /// Distance to the first wall triangle along the ray, or a negative value when none is hit
  /// within `max_distance_m` (bare rtcIntersect1 on the unfiltered scene: the benchmark's
  /// reference cost).
  double first_hit_m(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                     double max_distance_m) const;

  std::size_t triangle_count() const { return wall_ids_.size(); }

 private:
  struct Handles;
  std::unique_ptr<Handles> handles_;
  std::vector<int> wall_ids_;  // per Embree primitive
  std::vector<WallMaterial> materials_;
};

}  // namespace wifislam
