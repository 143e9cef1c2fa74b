#pragma once
// The generated world: a 2-D floor plan (free space, wall solids, doors) and a 3-D triangle mesh.
// Produced by the world generator (world_generator.hpp) from a Scene; read by the renderer
// (sim/render), the radio model (radio_model/), the robot (sim/robot) and eval's plots.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sim/scene/scene.hpp"

namespace wifislam::sim::world {

using Polygon2 = std::vector<Eigen::Vector2d>;  // simple polygon, counter-clockwise outer ring

struct PolygonWithHoles2 {
  Polygon2 outer;               // counter-clockwise
  std::vector<Polygon2> holes;  // clockwise
};

/// One face of a wall solid in the plan: a segment whose left side (walking from a to b) is
/// free space and right side is wall. Two faces belong to the same physical wall when they share
/// `wall_id`; the radio model counts each physical wall crossed once.
struct WallFace2 {
  Eigen::Vector2d a_m, b_m;
  radio_model::WallMaterial material = radio_model::WallMaterial::kPlasterboard;
  int wall_id = -1;
  int appearance_segment = -1;  // index into FloorPlan::appearance_segments
  /// True for the outside face of an outer wall: its left side is outside the building, not free
  /// space (such faces close the wall solids; they have no appearance segment).
  bool exterior = false;
  int door_index = -1;  // the closed door whose leaf this face is, else -1
};

/// A door in a wall between a corridor and a room.
struct Door {
  Eigen::Vector2d center_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d along_wall = Eigen::Vector2d::UnitX();  // unit vector along the wall
  double width_m = 0.9;
  double height_m = 2.1;
  double wall_thickness_m = 0.15;
  bool open = false;
  int room_index = -1;
};

struct Room {
  Polygon2 polygon_m;  // counter-clockwise, free space inside the room
  std::string corridor_id;
  int door_index = -1;
  radio_model::WallMaterial material = radio_model::WallMaterial::kBrick;
};

/// A piece of wall (appearance unit): its look is the shared one or its own (scene aliasing).
struct AppearanceSegment {
  int variant = 0;  // 0 = the shared look; k > 0 = a unique look
};

/// A ceiling light (for rendering and for lighting).
struct CeilingLight {
  Eigen::Vector3d center_m = Eigen::Vector3d::Zero();
  Eigen::Vector2d size_m = Eigen::Vector2d(0.6, 0.6);
};

struct FloorPlan {
  /// All free space: corridors, open areas, rooms and open door openings.
  std::vector<PolygonWithHoles2> free_space;
  /// Free space the robot may use: corridors and open areas (not rooms).
  std::vector<PolygonWithHoles2> walkable;
  /// Wall solids (2-D): what is neither free space nor outside the building.
  std::vector<PolygonWithHoles2> walls;
  std::vector<WallFace2> wall_faces;
  std::vector<Door> doors;
  std::vector<Room> rooms;
  std::vector<AppearanceSegment> appearance_segments;
  std::vector<CeilingLight> lights;
  Eigen::Vector2d bounds_min_m = Eigen::Vector2d::Zero(), bounds_max_m = Eigen::Vector2d::Zero();
  double wall_height_m = 2.8;
  double wall_thickness_m = 0.15;
  int wall_count = 0;  // wall ids of wall faces run from 0 to wall_count - 1
};

/// What a triangle is; the renderer picks a texture from this and the appearance variant.
enum class SurfaceKind : std::uint8_t {
  kWall,
  kFloor,
  kCeiling,
  kDoor,
  kDoorFrame,
  kPoster,
  kLight,
  kWallTop
};

struct Triangle {
  std::uint32_t v[3] = {0, 0, 0};  // indices into Mesh::positions_m (counter-clockwise seen from
                                   // the side the normal points to)
  SurfaceKind surface = SurfaceKind::kWall;
  radio_model::WallMaterial material =
      radio_model::WallMaterial::kPlasterboard;  // physical material (radio)
  int wall_id = -1;            // physical wall (radio counts crossings per wall); -1 = none
  int appearance_variant = 0;  // 0 = shared look; k > 0 unique (see Appearance::aliasing)
  int decoration = -1;         // poster/landmark design index for kPoster, else -1
};

/// Triangle mesh with per-vertex texture coordinates in metres (textures tile per metre, so
/// nothing stretches) and per-vertex normals (flat shading: vertices are not shared between
/// faces with different normals).
struct Mesh {
  std::vector<Eigen::Vector3f> positions_m;
  std::vector<Eigen::Vector3f> normals;
  std::vector<Eigen::Vector2f> uv_m;
  std::vector<Triangle> triangles;
};

/// The robot's route: a smooth 2-D path through walkable space, sampled densely.
struct RoutePath {
  std::vector<Eigen::Vector2d> points_m;  // spacing <= 0.05 m
  std::vector<double> arc_length_m;       // cumulative, same size as points_m
  std::vector<double> heading_rad;        // direction of travel at each point
  double length_m() const { return arc_length_m.empty() ? 0.0 : arc_length_m.back(); }
};

/// One level of a building of several (scene `levels:`): its plan, and its mesh in the
/// building's frame (z from the level's elevation). The radio model sees every storey's walls
/// and the slabs between them; the camera sees only the route's level.
struct Storey {
  std::string level_id;
  double elevation_m = 0.0;
  double slab_thickness_m = 0.0;
  radio_model::WallMaterial slab_material = radio_model::WallMaterial::kConcrete;
  FloorPlan plan;
  Mesh mesh;
};

struct World {
  /// The route's level: plan, mesh and route in the level's own frame (floor at z = 0), the
  /// frame of the camera, the robot and the ground truth.
  FloorPlan plan;
  Mesh mesh;
  RoutePath route;
  std::uint64_t seed = 0;
  /// The route level's floor in the building's frame (0 for a one-level scene): a receiver at
  /// height h above it stands at z = elevation_m + h among the storeys.
  double elevation_m = 0.0;
  std::string level_id;  // empty for a one-level scene
  /// Every level, lowest first, for a scene with `levels:`; empty for a one-level scene, whose
  /// plan and mesh above are the whole building.
  std::vector<Storey> storeys;
  /// The storey of level `id` (nullptr when there is none).
  const Storey* storey(const std::string& id) const {
    for (const Storey& s : storeys)
      if (s.level_id == id) return &s;
    return nullptr;
  }
};

}  // namespace wifislam::sim::world
