#pragma once
// The world's walls in Embree 3, for the question the radio model asks millions of times: which
// physical walls does the straight segment from an access point to a receiver cross?
//
// Built from the wall mesh it is handed (wall_mesh.hpp): the world's triangles with a wall_id >= 0
// (wall faces, closed door leaves, jambs, lintels; not floors, ceilings, wall tops or posters).
// Every such face bounds wall material and its free-space side (the mesh's normal) says on which
// side the material lies.
//
// Counting rule: the segment is cut at every face it hits; a piece of the segment is inside
// material when the face before it is entered (the segment runs against the face's normal) or
// the face after it is left (the segment runs along the normal). Consecutive inside pieces, and
// inside pieces separated by less than kTouchGapM (two coincident faces of touching solids: a
// lintel against its jamb, the end of one wall against another), form one crossing: one
// continuous stretch of material is one physical wall, however many wall pieces meet inside it.
// So a thick wall counts once, a ray through a T-junction counts once, a ray through the edge
// between a closed door leaf and the wall beside it counts once, and a ray that runs inside a
// wall along its length counts once. Stated edge cases:
//  - a stretch of material shorter than kMinCrossingM (a ray grazing a wall's corner) is a
//    touch, not a crossing;
//  - a ray in the plane of a face (grazing along it) sees no hit on that face: Embree reports no
//    intersection for a ray parallel to a triangle, so it crosses nothing there;
//  - the ends of the segment are excluded by a millimetre: a receiver standing on a face does not
//    cross that face;
//  - a crossing that enters through a face of one material and leaves through a face of another
//    (a door leaf and the wall beside it, a junction of a brick and a plasterboard wall) records
//    both materials; the radio model counts half a wall of each (the ray passes through some of
//    each; where the boundary between them lies inside the solid is not in the mesh).
//
// Two Embree scenes share the device: one with an occlusion filter that records every hit and
// rejects it so traversal continues (one traversal per segment, no restarts), one without
// filter for plain first-hit rays (an attached filter slows every query on its scene).
// Queries are const and thread-safe.

#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "radio_model/wall_material.hpp"
#include "radio_model/wall_mesh.hpp"

namespace wifislam::radio_model {

/// One continuous stretch of wall material on the segment.
struct WallCrossing {
  int wall_id = -1;                                          // wall of the face where it starts
  WallMaterial material = WallMaterial::kPlasterboard;       // of the face where it starts
  WallMaterial exit_material = WallMaterial::kPlasterboard;  // of the face where it ends
  double distance_m = 0.0;  // from the segment's start to where the material starts
  double length_m = 0.0;    // path length inside the material
  /// Whether the face where it starts is a floor slab's (WallMesh::Face::slab): the crossing is a
  /// floor. A stretch that runs from a wall straight into the slab it stands on is one crossing,
  /// named, like any other, after the face where it starts.
  bool slab = false;
};

class EmbreeWallScene {
 public:
  /// Throws EnvironmentError if Embree cannot create a device or scene.
  /// Throws InvalidInputError for a face with a negative wall id or a vertex index out of range.
  explicit EmbreeWallScene(const WallMesh& mesh);
  ~EmbreeWallScene();
  EmbreeWallScene(const EmbreeWallScene&) = delete;
  EmbreeWallScene& operator=(const EmbreeWallScene&) = delete;

  /// Stretches of material less than kTouchGapM (0.1 mm) apart are one crossing (coincident
  /// faces of touching solids); stretches shorter than kMinCrossingM (1 mm) are touches, not
  /// crossings.
  static constexpr double kTouchGapM = 1e-4;
  static constexpr double kMinCrossingM = 1e-3;

  /// Physical walls crossed strictly between `from` and `to` (the counting rule above), sorted
  /// by distance. `out` is cleared first; passing the same vector again avoids allocations.
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
  /// Whether any face is a floor slab's (a building of more than one storey).
  bool has_slabs() const { return has_slabs_; }

 private:
  /// Whether `point` lies inside wall material, by horizontal probes (used where the faces
  /// around a piece of segment disagree).
  bool inside_material(const Eigen::Vector3d& point, const Eigen::Vector3d& along) const;

  struct Handles;
  std::unique_ptr<Handles> handles_;
  std::vector<int> wall_ids_;  // per Embree primitive
  std::vector<WallMaterial> materials_;
  std::vector<std::uint8_t> slabs_;  // per primitive: 1 for a floor slab's face
  bool has_slabs_ = false;
  std::vector<Eigen::Vector3f> normals_;  // per primitive, toward free space
};

}  // namespace wifislam::radio_model
