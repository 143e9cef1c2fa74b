#include "floorplan/space_partition.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace wifislam::floorplan {

namespace {

int kind_rank(sim::SpaceKind kind) {
  switch (kind) {
    case sim::SpaceKind::kCorridor:
      return 0;
    case sim::SpaceKind::kArea:
      return 1;
    case sim::SpaceKind::kRoom:
      return 2;
  }
  return 3;
}

struct Box {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = Eigen::Vector2d::Constant(-1e300);
  void add(const PolygonRings& p) {
    for (const auto& v : p.outer) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  }
  bool near(const Box& o, double margin) const {
    return lo.x() <= o.hi.x() + margin && o.lo.x() <= hi.x() + margin &&
           lo.y() <= o.hi.y() + margin && o.lo.y() <= hi.y() + margin;
  }
};

/// Straight pieces (at least 0.2 m) of the lines, as consecutive point pairs.
void add_straight_pieces(const std::vector<Ring>& lines, int a, int b,
                         std::vector<SharedWall>& out) {
  for (const Ring& line : lines)
    for (std::size_t k = 0; k + 1 < line.size(); ++k)
      if ((line[k + 1] - line[k]).norm() >= 0.2) out.push_back({a, b, line[k], line[k + 1]});
}

}  // namespace

Partition partition_spaces(const GeosContext& geos, const std::vector<SpaceInput>& inputs,
                           const PartitionOptions& options) {
  const double grow_m = options.gap_close_m;
  std::vector<Geometry> drawn;
  std::vector<const Geometry*> drawn_ptrs;
  // On a 1 mm grid from the start: GEOS's overlay is robust on a fixed precision model.
  for (const SpaceInput& in : inputs) drawn.push_back(geos.polygon(in.polygon_m).snapped(0.001));
  for (const Geometry& g : drawn) drawn_ptrs.push_back(&g);
  // Step 1: footprint = closing of the union.
  const Geometry footprint = geos.union_all(drawn_ptrs)
                                 .buffer_mitre(grow_m)
                                 .buffer_mitre(-grow_m)
                                 .united(geos.union_all(drawn_ptrs));

  // Step 2, in priority order.
  std::vector<int> order(inputs.size());
  std::iota(order.begin(), order.end(), 0);
  std::vector<double> area(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) area[i] = drawn[i].area_m2();
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    const int ra = kind_rank(inputs[a].kind), rb = kind_rank(inputs[b].kind);
    return ra != rb ? ra < rb : area[a] > area[b];
  });
  // Each starts as drawn (minus what earlier spaces drew over), then all grow in turns of
  // kGrowStepM into the footprint nobody holds yet, so a gap is split near its middle: the
  // shared boundary is the drawn wall's centre line to within one step.
  std::vector<Geometry> grown(inputs.size());
  Geometry occupied = geos.empty_polygon();
  for (int i : order) {
    grown[i] = drawn[i].minus(occupied).polygonal();
    occupied = occupied.united(grown[i]).polygonal();
  }
  constexpr double kGrowStepM = 0.05;
  const int steps = static_cast<int>(std::ceil(grow_m / kGrowStepM));
  Geometry unclaimed = footprint.minus(occupied).polygonal();
  for (int step = 0; step < steps && !unclaimed.empty(); ++step) {
    for (int i : order) {
      if (grown[i].empty()) continue;
      Geometry gained = grown[i].buffer_mitre(kGrowStepM).intersected(unclaimed).polygonal();
      if (gained.empty()) continue;
      unclaimed = unclaimed.minus(gained).polygonal();
      grown[i] = grown[i].united(gained).polygonal();
    }
  }
  std::vector<Box> boxes(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i)
    for (const auto& p : grown[i].polygons()) boxes[i].add(p);

  Partition out;
  // Shared wall centre lines between neighbours.
  for (std::size_t a = 0; a < inputs.size(); ++a) {
    if (grown[a].empty()) continue;
    const Geometry boundary = grown[a].boundary();
    for (std::size_t b = a + 1; b < inputs.size(); ++b) {
      if (grown[b].empty() || !boxes[a].near(boxes[b], 0.05)) continue;
      const Geometry common = boundary.intersected(grown[b].buffer_mitre(0.01));
      if (!common.empty())
        add_straight_pieces(common.lines(), static_cast<int>(a), static_cast<int>(b),
                            out.shared_walls);
    }
  }
  // Step 3.
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    bool kept = false;
    if (!grown[i].empty()) {
      const Geometry free =
          grown[i].buffer_mitre(-0.5 * options.wall_thickness_m).snapped(0.001).simplified(0.005);
      for (PolygonRings& p : free.polygons()) {
        if (geos.polygon(p).area_m2() < options.min_area_m2) continue;
        out.pieces.push_back({static_cast<int>(i), std::move(p)});
        kept = true;
      }
    }
    if (!kept) out.dropped.push_back(static_cast<int>(i));
  }
  return out;
}

}  // namespace wifislam::floorplan
