#include "floorplan/space_partition.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "sim/world/box_grid.hpp"

namespace wifislam::floorplan {

namespace {

int kind_rank(sim::scene::SpaceKind kind) {
  switch (kind) {
    case sim::scene::SpaceKind::kCorridor:
      return 0;
    case sim::scene::SpaceKind::kArea:
      return 1;
    case sim::scene::SpaceKind::kRoom:
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

// Up to this many spaces (every plan we ship), step 2 works on geometries of the whole plan, as the
// shipped scenes were made. Above it, that is quadratic in the number of spaces, and step 2 works
// near each space instead: it subtracts only the earlier spaces near it (subtract_near_earlier),
// and grows into the unclaimed footprint cut into tiles (grow_into_tiles). The same areas, but
// GEOS may start a ring at another vertex or keep another collinear one, so the scene's bytes
// can differ; hence the two paths.
constexpr int kMaxSpacesForWholePlanGeometries = 300;

Box box_of(const Geometry& g) {
  Box box;
  for (const auto& p : g.polygons()) box.add(p);
  return box;
}

std::size_t vertex_count(const Geometry& g) {
  std::size_t n = 0;
  for (const auto& p : g.polygons()) {
    n += p.outer.size();
    for (const auto& h : p.holes) n += h.size();
  }
  return n;
}

/// Cuts `g` (within `box`) in halves across the box's longer side until each piece has at most
/// kTileVertices vertices or is at most 4 m across.
void cut_into_tiles(const GeosContext& geos, Geometry g, const Box& box,
                    std::vector<Geometry>& out) {
  constexpr std::size_t kTileVertices = 64;
  if (g.empty()) return;
  const Eigen::Vector2d size = box.hi - box.lo;
  if (vertex_count(g) <= kTileVertices || size.maxCoeff() <= 4.0) {
    out.push_back(std::move(g));
    return;
  }
  Box lower = box, upper = box;
  const int axis = size.x() >= size.y() ? 0 : 1;
  lower.hi[axis] = upper.lo[axis] = box.lo[axis] + 0.5 * size[axis];
  for (const Box& half : {lower, upper}) {  // they share the cut line: no area in both
    PolygonRings rect;
    rect.outer = {
        half.lo, {half.hi.x(), half.lo.y()}, half.hi, {half.lo.x(), half.hi.y()}, half.lo};
    cut_into_tiles(geos, g.intersected(geos.polygon(rect)).polygonal(), half, out);
  }
}

/// Step 2's start for large plans: each space as drawn minus the spaces placed before it that are
/// near it (within 0.01 m of its box); far spaces change nothing in the difference.
void subtract_near_earlier(const GeosContext& geos, const std::vector<Geometry>& drawn,
                           const std::vector<int>& order, std::vector<Geometry>& grown) {
  const Eigen::Vector2d margin = Eigen::Vector2d::Constant(0.01);
  sim::world::BoxGrid placed(8.0);
  const Geometry nothing = geos.empty_polygon();
  for (int i : order) {
    const Box box = box_of(drawn[i]);
    std::vector<const Geometry*> near;
    for (const int j : placed.near(box.lo - margin, box.hi + margin)) near.push_back(&grown[j]);
    grown[i] =
        (near.empty() ? drawn[i].minus(nothing) : drawn[i].minus(geos.union_all(near))).polygonal();
    if (!grown[i].empty()) {
      const Box grown_box = box_of(grown[i]);
      placed.add(i, grown_box.lo, grown_box.hi);
    }
  }
}

/// Step 2's growth for large plans: as the loop over one unclaimed geometry in partition_spaces,
/// with the unclaimed footprint cut into small tiles on a grid, so that a space's growth reads
/// only the tiles near it. The same areas are claimed by the same spaces in the same order.
void grow_into_tiles(const GeosContext& geos, const std::vector<int>& order, int steps,
                     double step_m, const Geometry& unclaimed, std::vector<Geometry>& grown) {
  std::vector<Geometry> tiles;
  Box all = box_of(unclaimed);  // grown a little so that the first cuts hold every vertex
  all.lo -= Eigen::Vector2d::Constant(1.0), all.hi += Eigen::Vector2d::Constant(1.0);
  cut_into_tiles(geos, unclaimed.clone(), all, tiles);
  sim::world::BoxGrid grid(8.0);
  std::vector<Box> tile_boxes;  // as cut (a tile only shrinks after)
  for (std::size_t t = 0; t < tiles.size(); ++t) {
    tile_boxes.push_back(box_of(tiles[t]));
    grid.add(static_cast<int>(t), tile_boxes.back().lo, tile_boxes.back().hi);
  }
  const Eigen::Vector2d reach = Eigen::Vector2d::Constant(step_m + 1e-3);
  for (int step = 0; step < steps; ++step) {
    bool any_left = false;
    for (const Geometry& t : tiles) any_left = any_left || !t.empty();
    if (!any_left) break;
    for (int i : order) {
      if (grown[i].empty()) continue;
      Box b = box_of(grown[i]);
      b.lo -= reach, b.hi += reach;
      // Every GEOS overlay has a fixed cost (its snap-rounding seeds a random engine), so the
      // tiles whose boxes miss the space's reach are skipped before any.
      std::vector<int> near;
      for (const int t : grid.near(b.lo, b.hi))
        if (!tiles[t].empty() && tile_boxes[t].near(b, 0.0)) near.push_back(t);
      if (near.empty()) continue;
      const Geometry reached = grown[i].buffer_mitre(step_m);
      std::vector<Geometry> parts;
      for (const int t : near) {
        Geometry part = reached.intersected(tiles[t]).polygonal();
        if (part.empty()) continue;
        tiles[t] = tiles[t].minus(part).polygonal();
        parts.push_back(std::move(part));
      }
      if (parts.empty()) continue;
      std::vector<const Geometry*> part_ptrs;
      for (const Geometry& part : parts) part_ptrs.push_back(&part);
      grown[i] = grown[i].united(geos.union_all(part_ptrs)).polygonal();
    }
  }
}

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
  const Geometry drawn_union = geos.union_all(drawn_ptrs);
  const Geometry footprint =
      drawn_union.buffer_mitre(grow_m).buffer_mitre(-grow_m).united(drawn_union);

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
  const bool whole_plan = static_cast<int>(inputs.size()) <= kMaxSpacesForWholePlanGeometries;
  Geometry occupied = geos.empty_polygon();
  if (whole_plan) {
    for (int i : order) {
      grown[i] = drawn[i].minus(occupied).polygonal();
      occupied = occupied.united(grown[i]).polygonal();
    }
  } else {
    subtract_near_earlier(geos, drawn, order, grown);
    std::vector<const Geometry*> grown_ptrs;
    for (const Geometry& g : grown) grown_ptrs.push_back(&g);
    occupied = geos.union_all(grown_ptrs).polygonal();
  }
  constexpr double kGrowStepM = 0.05;
  const int steps = static_cast<int>(std::ceil(grow_m / kGrowStepM));
  Geometry unclaimed = footprint.minus(occupied).polygonal();
  if (whole_plan) {
    for (int step = 0; step < steps && !unclaimed.empty(); ++step) {
      for (int i : order) {
        if (grown[i].empty()) continue;
        Geometry gained = grown[i].buffer_mitre(kGrowStepM).intersected(unclaimed).polygonal();
        if (gained.empty()) continue;
        unclaimed = unclaimed.minus(gained).polygonal();
        grown[i] = grown[i].united(gained).polygonal();
      }
    }
  } else {
    grow_into_tiles(geos, order, steps, kGrowStepM, unclaimed, grown);
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
