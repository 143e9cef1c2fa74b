// Digest of wall_crossed's answers on every shipped scene, to show that a change of how walls are
// counted (embree_wall_scene.cpp) leaves every answer bit for bit unchanged: run it before and
// after, compare the lines. Per scene: SHA-256 over every field of every crossing (wall id, both
// materials, distance and length as their IEEE bytes) of 200000 segments from one named stream:
// random ends over the plan's bounds at random heights (0-3.2 m), lengths 0-60 m, a tenth of them
// axis-aligned (runs along wall faces and through edges and junctions, the counting rule's stated
// edge cases), and a tenth from one end of another segment (a receiver or an AP shared by links).
//
//   build/release/bench/radio_model/wall_crossing_digest [SCENE.yaml ...]   (default:
//   scenes/*.yaml)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/rng.hpp"
#include "radio_model/embree_wall_scene.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/world/radio_wall_mesh.hpp"
#include "sim/world/world_generator.hpp"

namespace {

using namespace wifislam;

template <typename T>
void append(std::string& bytes, const T& value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  bytes.append(raw, sizeof(T));
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) files.emplace_back(argv[i]);
  if (files.empty()) {
    for (const auto& entry : std::filesystem::directory_iterator(WIFISLAM_SCENES_DIR))
      if (entry.path().extension() == ".yaml") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
  }
  constexpr int kSegments = 200000;
  for (const std::string& file : files) {
    const sim::world::World world = sim::world::generate_world(sim::scene::load_scene_file(file));
    const radio_model::EmbreeWallScene walls(sim::world::radio_wall_mesh(world.mesh));
    const Eigen::Vector2d lo = world.plan.bounds_min_m, hi = world.plan.bounds_max_m;
    Rng rng = Rng::stream(7, "bench/wall_crossing_digest");
    std::string bytes;
    std::vector<radio_model::WallCrossing> out;
    std::size_t crossings = 0;
    Eigen::Vector3d previous = Eigen::Vector3d::Zero();
    for (int i = 0; i < kSegments; ++i) {
      const Eigen::Vector3d a =
          i % 10 == 5 ? previous
                      : Eigen::Vector3d(rng.uniform(lo.x(), hi.x()), rng.uniform(lo.y(), hi.y()),
                                        rng.uniform(0.0, 3.2));
      const double length = rng.uniform(0.0, 60.0);
      double heading = rng.uniform(0.0, 2.0 * M_PI);
      if (i % 10 == 0) heading = std::round(heading / (0.5 * M_PI)) * 0.5 * M_PI;
      const Eigen::Vector3d b(a.x() + length * std::cos(heading),
                              a.y() + length * std::sin(heading),
                              i % 10 == 0 ? a.z() : rng.uniform(0.0, 3.2));
      previous = b;
      walls.walls_crossed(a, b, out);
      append(bytes, out.size());
      for (const radio_model::WallCrossing& c : out) {
        append(bytes, c.wall_id);
        append(bytes, c.material);
        append(bytes, c.exit_material);
        append(bytes, c.distance_m);
        append(bytes, c.length_m);
      }
      crossings += out.size();
    }
    std::printf("%s  %d segments, %zu crossings, sha256 %s\n",
                std::filesystem::path(file).filename().c_str(), kSegments, crossings,
                sha256_hex(bytes).c_str());
  }
  return 0;
}
