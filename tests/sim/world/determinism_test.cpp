#include <gtest/gtest.h>

#include <map>
#include <set>

#include "sim/world/floor_plan_builder.hpp"
#include "sim/world/poster_layout.hpp"
#include "sim/world/world_generator.hpp"
#include "tests/sim/world/world_test_support.hpp"

namespace wifislam::sim {
namespace {

std::vector<int> variants(const world::FloorPlan& plan) {
  std::vector<int> v;
  for (const auto& s : plan.appearance_segments) v.push_back(s.variant);
  return v;
}

std::multiset<int> poster_designs(const scene::Scene& scene, const world::FloorPlan& plan) {
  std::multiset<int> d;
  for (const auto& p : world::place_posters(scene, plan)) d.insert(p.decoration);
  return d;
}

TEST(Determinism, SameSceneAndSeedGiveIdenticalMeshHash) {
  const scene::Scene scene = test::square_loop_scene();
  const world::World a = world::generate_world(scene);
  const world::World b = world::generate_world(scene);
  EXPECT_EQ(world::mesh_hash(a.mesh), world::mesh_hash(b.mesh));
  EXPECT_EQ(a.route.points_m, b.route.points_m);
}

TEST(Determinism, DifferentSeedChangesAppearanceWhenAliasingBelowOne) {
  scene::Scene scene = test::square_loop_scene();
  scene.appearance.aliasing = 0.5;
  const world::FloorPlan a = world::build_floor_plan(scene);
  scene.seed += 1;
  const world::FloorPlan b = world::build_floor_plan(scene);
  EXPECT_NE(variants(a), variants(b));
  EXPECT_NE(poster_designs(scene, a), poster_designs(scene, b));
  EXPECT_NE(world::mesh_hash(world::generate_world(scene).mesh),
            world::mesh_hash(world::generate_world(test::square_loop_scene()).mesh));
}

TEST(Determinism, FullAliasingGivesEverySegmentTheSameLookAndPosters) {
  scene::Scene scene = test::square_loop_scene();
  scene.appearance.aliasing = 1.0;
  scene.appearance.posters_per_10m = 5.0;  // two per 4 m segment
  for (std::uint64_t seed : {1u, 2u}) {
    scene.seed = seed;
    const world::FloorPlan plan = world::build_floor_plan(scene);
    for (int v : variants(plan)) EXPECT_EQ(v, 0);
    // Segments of equal length carry posters at the same places with the same designs.
    std::map<long long, std::vector<std::pair<double, int>>> by_length;
    std::map<int, std::vector<std::pair<double, int>>> by_face;
    for (const auto& p : world::place_posters(scene, plan)) {
      const world::WallFace2& f = plan.wall_faces[p.face_index];
      by_face[p.face_index].emplace_back((p.center_m - f.a_m).norm(), p.decoration);
    }
    int compared = 0;
    for (const auto& [face, posters] : by_face) {
      const world::WallFace2& f = plan.wall_faces[face];
      const long long key = std::llround((f.b_m - f.a_m).norm() * 1e6);
      auto [it, inserted] = by_length.emplace(key, posters);
      if (inserted) continue;
      ASSERT_EQ(it->second.size(), posters.size());
      for (std::size_t k = 0; k < posters.size(); ++k) {
        EXPECT_NEAR(it->second[k].first, posters[k].first, 1e-9);
        EXPECT_EQ(it->second[k].second, posters[k].second);
      }
      ++compared;
    }
    EXPECT_GT(compared, 10);
  }
}

TEST(Determinism, NoAliasingGivesEverySegmentItsOwnLook) {
  scene::Scene scene = test::square_loop_scene();
  scene.appearance.aliasing = 0.0;
  const world::FloorPlan plan = world::build_floor_plan(scene);
  const std::vector<int> v = variants(plan);
  const std::set<int> distinct(v.begin(), v.end());
  EXPECT_EQ(distinct.size(), v.size());
  EXPECT_EQ(distinct.count(0), 0u);
  const auto designs = poster_designs(scene, plan);
  EXPECT_EQ(std::set<int>(designs.begin(), designs.end()).size(), designs.size());
}

}  // namespace
}  // namespace wifislam::sim
