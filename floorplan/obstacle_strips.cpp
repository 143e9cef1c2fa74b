#include "floorplan/obstacle_strips.hpp"

#include <algorithm>

#include <Eigen/Geometry>

namespace wifislam::floorplan {

namespace {

Eigen::AlignedBox2d box_of(const Ring& ring) {
  Eigen::AlignedBox2d box;
  for (const Eigen::Vector2d& p : ring) box.extend(p);
  return box;
}

// A strip shares its long edges with the space's outline and the obstacle exactly as GEOS
// computed them; grown by this much it overlaps both, so that the world builder's exact
// arithmetic leaves no hair of free space along either edge. Far below anything a robot or a
// renderer resolves.
constexpr double kStripOverlapM = 0.001;

}  // namespace

int make_cut_off_strips_solid(const GeosContext& geos, const Partition& partition,
                              double min_area_m2, double wall_thickness_m,
                              std::vector<sim::scene::Obstacle>& obstacles) {
  std::vector<Geometry> shapes;
  std::vector<Eigen::AlignedBox2d> boxes;
  std::vector<bool> usable;
  for (const sim::scene::Obstacle& o : obstacles) {
    Geometry g = o.polygon_m.size() >= 3 ? geos.polygon({o.polygon_m, {}}) : geos.empty_polygon();
    usable.push_back(!g.empty() && g.invalid_reason().empty());
    shapes.push_back(std::move(g));
    boxes.push_back(box_of(o.polygon_m));
  }
  int strips = 0;
  for (const SpacePiece& piece : partition.pieces) {
    const Eigen::AlignedBox2d piece_box = box_of(piece.free_m.outer);
    std::vector<int> near;
    std::vector<const Geometry*> near_shapes;
    for (std::size_t j = 0; j < obstacles.size(); ++j) {
      if (!usable[j] || !boxes[j].intersects(piece_box)) continue;
      near.push_back(static_cast<int>(j));
      near_shapes.push_back(&shapes[j]);
    }
    if (near.empty()) continue;
    const Geometry free = geos.polygon(piece.free_m).minus(geos.union_all(near_shapes)).polygonal();
    const std::vector<PolygonRings> parts = free.polygons();
    if (parts.size() < 2) continue;
    std::vector<double> area_m2;
    for (const PolygonRings& p : parts) area_m2.push_back(geos.polygon(p).area_m2());
    const std::size_t largest = static_cast<std::size_t>(
        std::max_element(area_m2.begin(), area_m2.end()) - area_m2.begin());
    for (std::size_t k = 0; k < parts.size(); ++k) {
      if (k == largest) continue;
      const Geometry part = geos.polygon(parts[k]);
      // Narrower than a wall everywhere: shrunk by half a wall, nothing is left.
      const bool strip =
          area_m2[k] < min_area_m2 || part.buffer_mitre(-0.5 * wall_thickness_m).empty();
      if (!strip) continue;
      const Geometry grown = part.buffer_mitre(kStripOverlapM);
      for (int j : near) {
        if (grown.intersected(shapes[j]).polygonal().empty()) continue;
        const std::vector<PolygonRings> merged = shapes[j].united(grown).polygonal().polygons();
        const auto biggest = std::max_element(
            merged.begin(), merged.end(), [&](const PolygonRings& a, const PolygonRings& b) {
              return geos.polygon(a).area_m2() < geos.polygon(b).area_m2();
            });
        obstacles[j].polygon_m = biggest->outer;
        shapes[j] = geos.polygon({biggest->outer, {}});
        boxes[j] = box_of(biggest->outer);
        ++strips;
        break;
      }
    }
  }
  return strips;
}

}  // namespace wifislam::floorplan
