#include "sim/world/ceiling_lights.hpp"

#include <algorithm>
#include <cmath>

#include "core/rng.hpp"
#include "sim/world/box_grid.hpp"
#include "sim/world/plan_queries.hpp"
#include "sim/world/region_locator.hpp"

namespace wifislam::sim::world {

std::vector<CeilingLight> place_ceiling_lights(const scene::Scene& scene, const PlanLayout& layout,
                                               const FloorPlan& plan) {
  const double spacing = std::max(0.5, scene.appearance.light_spacing_m);
  const double z = plan.wall_height_m - 0.01;
  const Eigen::Vector2d size(0.6, 0.6);
  std::vector<CeilingLight> lights;
  // Free space and the lights so far are looked up near the candidate, not scanned whole (a
  // building of 10 000 rooms has tens of thousands of lights): the same answers.
  const RegionLocator free_space(plan.free_space);
  BoxGrid near_lights(spacing);
  auto try_add = [&](const Eigen::Vector2d& p, double min_gap_m) {
    // All four corners in free space, so no light pokes into a wall.
    for (double sx : {-0.5, 0.5})
      for (double sy : {-0.5, 0.5})
        if (free_space.find(p + Eigen::Vector2d(sx * size.x(), sy * size.y())) < 0) return;
    const Eigen::Vector2d gap = Eigen::Vector2d::Constant(min_gap_m);
    for (const int l : near_lights.near(p - gap, p + gap))
      if ((lights[l].center_m.head<2>() - p).norm() < min_gap_m) return;
    CeilingLight light;
    light.center_m = Eigen::Vector3d(p.x(), p.y(), z);
    light.size_m = size;
    near_lights.add(static_cast<int>(lights.size()), p, p);
    lights.push_back(light);
  };
  // Along corridors each light is shifted by up to 20 % of the spacing (seeded): with a strictly
  // periodic row, any two places a few spacings apart share an identical constellation of lights,
  // enough for a feature matcher to "recognise" one as the other whatever the walls look like.
  Rng rng = Rng::stream(scene.seed, "appearance/lights");
  for (const CorridorLayout& c : layout.corridors) {
    const int n = std::max(1, static_cast<int>(std::floor(c.length_m / spacing)));
    for (int k = 0; k < n; ++k) {
      const double shift = n > 1 ? rng.uniform(-0.2, 0.2) : 0.0;
      try_add(c.rect.point((k + 0.5 + shift) * c.length_m / n, 0.0), 0.5 * spacing);
    }
  }
  for (const scene::OpenArea& area : scene.open_areas) {
    Eigen::Vector2d lo = area.polygon_m[0], hi = area.polygon_m[0];
    for (const auto& v : area.polygon_m) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    for (double y = lo.y() + 0.5 * spacing; y < hi.y(); y += spacing)
      for (double x = lo.x() + 0.5 * spacing; x < hi.x(); x += spacing)
        if (ring_contains(area.polygon_m, {x, y})) try_add({x, y}, 0.5 * spacing);
  }
  // Walkable spaces of imported plans: candidates on a grid of a third of the spacing, centred
  // on the space's box, kept a spacing apart (a narrow corridor of any shape still gets a row).
  for (const scene::Space& space : scene.spaces) {
    if (space.kind == scene::SpaceKind::kRoom) continue;
    Eigen::Vector2d lo = space.polygon_m[0], hi = space.polygon_m[0];
    for (const auto& v : space.polygon_m) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    const Eigen::Vector2d mid = 0.5 * (lo + hi);
    const RegionLocator inside({PolygonWithHoles2{space.polygon_m, {}}});  // == ring_contains
    const double step = spacing / 3;
    const int nx = static_cast<int>(std::ceil(0.5 * (hi.x() - lo.x()) / step));
    const int ny = static_cast<int>(std::ceil(0.5 * (hi.y() - lo.y()) / step));
    for (int j = -ny; j <= ny; ++j)
      for (int i = -nx; i <= nx; ++i) {
        const Eigen::Vector2d p = mid + step * Eigen::Vector2d(i, j);
        if (inside.find(p) == 0) try_add(p, spacing);
      }
  }
  for (const Room& room : plan.rooms) {
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (const auto& v : room.polygon_m) c += v;
    try_add(c / static_cast<double>(room.polygon_m.size()), 0.5);
  }
  return lights;
}

}  // namespace wifislam::sim::world
