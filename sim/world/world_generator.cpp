#include "sim/world/world_generator.hpp"

#include <algorithm>
#include <cstring>

#include <fmt/format.h>

#include "core/dataset_format.hpp"
#include "core/error.hpp"
#include "sim/scene/scene_levels.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/world/floor_plan_builder.hpp"
#include "sim/world/mesh_builder.hpp"
#include "sim/world/plan_queries.hpp"
#include "sim/world/route_builder.hpp"

namespace wifislam::sim::world {

namespace {

Mesh raised_by(Mesh mesh, double dz_m) {
  for (Eigen::Vector3f& p : mesh.positions_m) p.z() += static_cast<float>(dz_m);
  return mesh;
}

}  // namespace

World generate_world(const scene::Scene& scene) {
  World world;
  world.seed = scene.seed;
  if (!scene::has_levels(scene)) {
    world.plan = build_floor_plan(scene);
    world.route = build_route(scene, world.plan);
    world.mesh = build_mesh(scene, world.plan);
    return world;
  }
  // Every level is built as a one-level scene of its own pieces (scene_on_level); the route's
  // level also gets the route. Lowest first: the radio model takes storeys in that order.
  std::vector<scene::ResolvedLevel> levels = scene::resolved_levels(scene);
  std::stable_sort(levels.begin(), levels.end(),
                   [](const scene::ResolvedLevel& a, const scene::ResolvedLevel& b) {
                     return a.elevation_m < b.elevation_m;
                   });
  world.level_id = scene::route_level(scene);
  for (const scene::ResolvedLevel& level : levels) {
    const scene::Scene part = scene::scene_on_level(scene, level.id);
    Storey storey;
    storey.level_id = level.id;
    storey.elevation_m = level.elevation_m;
    storey.slab_thickness_m = level.slab_thickness_m;
    storey.slab_material = level.slab_material;
    storey.plan = build_floor_plan(part, level.id == world.level_id);
    Mesh mesh = build_mesh(part, storey.plan);
    if (level.id == world.level_id) {
      world.plan = storey.plan;
      world.route = build_route(part, world.plan);
      world.elevation_m = level.elevation_m;
      world.mesh = mesh;
    }
    storey.mesh = raised_by(std::move(mesh), level.elevation_m);
    world.storeys.push_back(std::move(storey));
  }
  return world;
}

std::optional<World> dataset_world(const std::filesystem::path& dataset_dir, std::string& why_not) {
  const std::filesystem::path scene = dataset_dir / dataset::kScene;
  if (!std::filesystem::exists(scene)) {
    why_not = "the dataset has no scene.yaml";
    return std::nullopt;
  }
  try {
    return generate_world(scene::load_scene_file(scene.string()));
  } catch (const Error& e) {
    why_not = e.what();
    return std::nullopt;
  }
}

namespace {

struct Fnv1a {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  void bytes(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) {
      h ^= p[i];
      h *= 0x100000001b3ULL;
    }
  }
  template <typename T>
  void value(const T& v) {
    bytes(&v, sizeof v);
  }
};

}  // namespace

std::uint64_t mesh_hash(const Mesh& mesh) {
  Fnv1a f;
  // Field by field, so struct padding never enters the hash.
  f.value(mesh.positions_m.size());
  for (const auto& p : mesh.positions_m) f.value(p.x()), f.value(p.y()), f.value(p.z());
  for (const auto& n : mesh.normals) f.value(n.x()), f.value(n.y()), f.value(n.z());
  for (const auto& uv : mesh.uv_m) f.value(uv.x()), f.value(uv.y());
  f.value(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) {
    f.value(t.v[0]), f.value(t.v[1]), f.value(t.v[2]);
    f.value(static_cast<std::uint8_t>(t.surface));
    f.value(static_cast<std::int32_t>(t.material));
    f.value(static_cast<std::int32_t>(t.wall_id));
    f.value(static_cast<std::int32_t>(t.appearance_variant));
    f.value(static_cast<std::int32_t>(t.decoration));
  }
  return f.h;
}

WorldSummary summarize_world(const World& world) {
  WorldSummary s;
  s.free_area_m2 = regions_area_m2(world.plan.free_space);
  s.walkable_area_m2 = regions_area_m2(world.plan.walkable);
  double faces = 0;
  for (const WallFace2& f : world.plan.wall_faces) faces += (f.b_m - f.a_m).norm();
  s.wall_length_m = 0.5 * faces;
  s.triangles = world.mesh.triangles.size();
  s.rooms = world.plan.rooms.size();
  s.doors = world.plan.doors.size();
  s.route_length_m = world.route.length_m();
  return s;
}

std::string WorldSummary::to_text() const {
  return fmt::format(
      "free area: {:.1f} m2\n"
      "walkable area: {:.1f} m2\n"
      "wall length: {:.1f} m\n"
      "triangles: {}\n"
      "rooms: {}\n"
      "doors: {}\n"
      "route length: {:.1f} m\n",
      free_area_m2, walkable_area_m2, wall_length_m, triangles, rooms, doors, route_length_m);
}

}  // namespace wifislam::sim::world
