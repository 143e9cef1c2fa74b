#include "floorplan/route_planner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "sim/world/wall_face_grid.hpp"

namespace wifislam::floorplan {

namespace {

struct Grid {
  Eigen::Vector2d origin_m;
  double cell_m;
  int width, height;
  cv::Mat1f clearance_m;  // 0 outside walkable space
  cv::Mat1i piece;        // connected piece of cells with enough clearance, 0 = none

  Eigen::Vector2d centre_of(int index) const {
    return origin_m + cell_m * Eigen::Vector2d(index % width + 0.5, index / width + 0.5);
  }
  int index_of(const Eigen::Vector2d& p) const {
    const int x = static_cast<int>(std::floor((p.x() - origin_m.x()) / cell_m));
    const int y = static_cast<int>(std::floor((p.y() - origin_m.y()) / cell_m));
    if (x < 0 || y < 0 || x >= width || y >= height) return -1;
    return y * width + x;
  }
  float clearance(int index) const { return clearance_m(index / width, index % width); }
};

std::vector<cv::Point> to_pixels(const sim::Polygon2& ring, const Grid& g) {
  std::vector<cv::Point> out;
  for (const auto& p : ring) {
    const Eigen::Vector2d q = (p - g.origin_m) / g.cell_m;
    out.emplace_back(static_cast<int>(std::lround(q.x() - 0.5)),
                     static_cast<int>(std::lround(q.y() - 0.5)));
  }
  return out;
}

// The grid's cells at most: its rasters take ~13 bytes a cell (walkable, clearance, labels),
// so ~0.5 GB. A building of 600 m x 600 m keeps the 0.1 m cells; a plan spread over kilometres
// (a campus, or one stray feature far from the rest) gets coarser cells instead of tens of GB.
constexpr double kMaxGridCells = 36e6;
// Walk costs kept for every target at most (12 bytes each): see plan_tour.
constexpr double kMaxKeptCostCells = 40e6;

Grid make_grid(const sim::FloorPlan& plan, const TourOptions& options) {
  Grid g;
  g.origin_m = plan.bounds_min_m - Eigen::Vector2d::Constant(1.0);
  const Eigen::Vector2d size = plan.bounds_max_m - g.origin_m + Eigen::Vector2d::Constant(1.0);
  g.cell_m = std::max(options.cell_m, std::sqrt(size.x() * size.y() / kMaxGridCells));
  g.width = static_cast<int>(std::ceil(size.x() / g.cell_m));
  g.height = static_cast<int>(std::ceil(size.y() / g.cell_m));
  cv::Mat1b walkable(g.height, g.width, static_cast<unsigned char>(0));
  for (const auto& region : plan.walkable) {
    cv::fillPoly(walkable, std::vector<std::vector<cv::Point>>{to_pixels(region.outer, g)},
                 cv::Scalar(255));
    for (const auto& hole : region.holes)
      cv::fillPoly(walkable, std::vector<std::vector<cv::Point>>{to_pixels(hole, g)},
                   cv::Scalar(0));
  }
  cv::Mat1f distance_px;
  cv::distanceTransform(walkable, distance_px, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  g.clearance_m = distance_px * g.cell_m;
  // The raster knows walkable space; the wall faces (door leaves, wall ends the raster rounds
  // off) are measured exactly, as the route builder will.
  const double reach_m = options.clearance_m + 0.5;
  const sim::WallFaceGrid faces(plan, reach_m);
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      float& c = g.clearance_m(y, x);
      if (c <= 0) continue;
      c = std::min(
          c, static_cast<float>(faces.nearest_within_m(g.centre_of(y * g.width + x), reach_m)));
    }
  cv::Mat1b roomy = g.clearance_m >= options.clearance_m;
  cv::Mat1i labels, stats;
  cv::Mat1d centroids;
  const int n = cv::connectedComponentsWithStats(roomy, labels, stats, centroids, 8, CV_32S);
  int best = 0;
  for (int k = 1; k < n; ++k)
    if (best == 0 || stats(k, cv::CC_STAT_AREA) > stats(best, cv::CC_STAT_AREA)) best = k;
  if (best == 0)
    throw InvalidInputError(fmt::format(
        "no walkable space keeps {:.2f} m from every wall: the corridors are too narrow for a "
        "route",
        options.clearance_m));
  g.piece = labels == best;
  g.piece /= 255;
  return g;
}

/// Walking costs from `source` to every cell of the piece (Dijkstra, 8-neighbours), with the
/// predecessor of each cell. A step costs its length times (1 + 0.5 m / clearance): the middle of
/// a corridor is cheaper than its sides.
struct Costs {
  std::vector<double> cost;
  std::vector<int> previous;
};

Costs walk_costs(const Grid& g, int source) {
  const int n = g.width * g.height;
  Costs c{std::vector<double>(n, std::numeric_limits<double>::infinity()), std::vector<int>(n, -1)};
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  c.cost[source] = 0;
  open.push({0.0, source});
  static const int dx[8] = {1, -1, 0, 0, 1, 1, -1, -1}, dy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
  while (!open.empty()) {
    const auto [cost, i] = open.top();
    open.pop();
    if (cost > c.cost[i]) continue;
    const int x = i % g.width, y = i / g.width;
    for (int k = 0; k < 8; ++k) {
      const int nx = x + dx[k], ny = y + dy[k];
      if (nx < 0 || ny < 0 || nx >= g.width || ny >= g.height || !g.piece(ny, nx)) continue;
      const int j = ny * g.width + nx;
      const double step = (k < 4 ? 1.0 : M_SQRT2) * g.cell_m;
      const double next = cost + step * (1.0 + 0.5 / std::max(0.05f, g.clearance(j)));
      if (next < c.cost[j]) {
        c.cost[j] = next;
        c.previous[j] = i;
        open.push({next, j});
      }
    }
  }
  return c;
}

/// The cell of the piece nearest to p (within 3 m), or -1.
int snap(const Grid& g, const Eigen::Vector2d& p) {
  const int r = static_cast<int>(std::ceil(3.0 / g.cell_m));
  const int i0 = g.index_of(p);
  if (i0 < 0) return -1;
  int best = -1;
  double best_d = 1e300;
  for (int y = i0 / g.width - r; y <= i0 / g.width + r; ++y)
    for (int x = i0 % g.width - r; x <= i0 % g.width + r; ++x) {
      if (x < 0 || y < 0 || x >= g.width || y >= g.height || !g.piece(y, x)) continue;
      const double d = (g.centre_of(y * g.width + x) - p).norm();
      if (d < best_d) best_d = d, best = y * g.width + x;
    }
  return best;
}

/// Farthest-point sampling of the piece, from the given targets (or its roomiest cell).
std::vector<int> spread_targets(const Grid& g, double spacing_m, std::vector<int> targets) {
  std::vector<int> cells;
  int start = -1;
  for (int i = 0; i < g.width * g.height; ++i) {
    if (!g.piece(i / g.width, i % g.width)) continue;
    cells.push_back(i);
    if (start < 0 || g.clearance(i) > g.clearance(start)) start = i;
  }
  if (targets.empty()) targets.push_back(start);
  std::vector<double> nearest(cells.size(), 1e300);
  for (std::size_t t = 0; t + 1 < targets.size(); ++t)
    for (std::size_t k = 0; k < cells.size(); ++k)
      nearest[k] = std::min(nearest[k], (g.centre_of(cells[k]) - g.centre_of(targets[t])).norm());
  while (true) {
    const Eigen::Vector2d t = g.centre_of(targets.back());
    std::size_t far = 0;
    for (std::size_t k = 0; k < cells.size(); ++k) {
      nearest[k] = std::min(nearest[k], (g.centre_of(cells[k]) - t).norm());
      if (nearest[k] > nearest[far]) far = k;
    }
    if (nearest[far] < spacing_m) break;
    targets.push_back(cells[far]);
  }
  return targets;
}

/// Tour order over targets by walking distance: nearest neighbour, then 2-opt.
std::vector<int> tour_order(const std::vector<std::vector<double>>& d) {
  const std::size_t n = d.size();
  std::vector<int> order{0};
  std::vector<bool> used(n, false);
  used[0] = true;
  for (std::size_t step = 1; step < n; ++step) {
    int next = -1;
    for (std::size_t j = 0; j < n; ++j)
      if (!used[j] && (next < 0 || d[order.back()][j] < d[order.back()][next]))
        next = static_cast<int>(j);
    used[next] = true;
    order.push_back(next);
  }
  for (bool improved = true; improved;) {
    improved = false;
    for (std::size_t i = 1; i + 1 < n; ++i)
      for (std::size_t k = i + 1; k < n; ++k) {
        const int a = order[i - 1], b = order[i], c = order[k], e = order[(k + 1) % n];
        if (d[a][c] + d[b][e] < d[a][b] + d[c][e] - 1e-9) {
          std::reverse(order.begin() + static_cast<long>(i),
                       order.begin() + static_cast<long>(k) + 1);
          improved = true;
        }
      }
  }
  return order;
}

/// Whether the straight segment keeps the clearance (samples every half cell).
bool clear_line(const Grid& g, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / (0.5 * g.cell_m))));
  for (int k = 0; k <= n; ++k) {
    const int i = g.index_of(a + (b - a) * (double(k) / n));
    if (i < 0 || !g.piece(i / g.width, i % g.width)) return false;
  }
  return true;
}

/// The cells of a leg as points, shortcut greedily while the line stays clear.
std::vector<Eigen::Vector2d> shortcut(const Grid& g, const std::vector<int>& cells) {
  std::vector<Eigen::Vector2d> out{g.centre_of(cells.front())};
  std::size_t at = 0;
  while (at + 1 < cells.size()) {
    std::size_t next = at + 1;
    for (std::size_t k = cells.size() - 1; k > at + 1; --k)
      if (clear_line(g, g.centre_of(cells[at]), g.centre_of(cells[k]))) {
        next = k;
        break;
      }
    out.push_back(g.centre_of(cells[next]));
    at = next;
  }
  return out;
}

}  // namespace

std::vector<Eigen::Vector2d> plan_tour(const sim::FloorPlan& plan,
                                       const std::vector<Eigen::Vector2d>& must_visit,
                                       const TourOptions& options, bool keep_order) {
  const Grid g = make_grid(plan, options);
  std::vector<int> targets;
  for (std::size_t i = 0; i < must_visit.size(); ++i) {
    const Eigen::Vector2d& p = must_visit[i];
    const int cell = snap(g, p);
    // The user's waypoints are the route: one that cannot be reached is an error, not a point
    // to drop (a plan's own paths may leave the walkable space; those points are skipped).
    if (cell < 0 && keep_order)
      throw InvalidInputError(fmt::format(
          "route waypoint {} ({:.2f}, {:.2f}) is not within 3 m of the walkable space (the plan "
          "spans x {:.1f} to {:.1f} m, y {:.1f} to {:.1f} m)",
          i + 1, p.x(), p.y(), plan.bounds_min_m.x(), plan.bounds_max_m.x(), plan.bounds_min_m.y(),
          plan.bounds_max_m.y()));
    if (cell >= 0 && (targets.empty() || targets.back() != cell)) targets.push_back(cell);
  }
  // The user's waypoints are the route; a plan's paths are visited among points spread over the
  // whole walkable space (WRLD paths often cover only stairs and entrances).
  const bool given = keep_order && targets.size() >= 2;
  if (!given) targets = spread_targets(g, options.target_spacing_m, targets);
  if (targets.size() < 2)
    throw InvalidInputError("the walkable space is too small for a route with a loop");
  // Every target's walk costs over the whole grid are kept for the legs when they fit in
  // ~0.5 GB; else (a long plan: hundreds of targets over millions of cells) each leg's are
  // computed again, the same numbers, so the route is the same either way.
  const bool keep_costs =
      static_cast<double>(targets.size()) * g.width * g.height <= kMaxKeptCostCells;
  std::vector<Costs> costs;
  std::vector<std::vector<double>> d(targets.size(), std::vector<double>(targets.size()));
  for (std::size_t a = 0; a < targets.size(); ++a) {
    Costs from_a = walk_costs(g, targets[a]);
    for (std::size_t b = 0; b < targets.size(); ++b) d[a][b] = from_a.cost[targets[b]];
    if (keep_costs) costs.push_back(std::move(from_a));
  }
  std::vector<int> order(targets.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  if (!given) order = tour_order(d);
  order.push_back(order.front());  // a closed loop: the start is seen again

  std::vector<Eigen::Vector2d> lap;
  for (std::size_t k = 0; k + 1 < order.size(); ++k) {
    // The leg from order[k] to order[k+1]: walk back the predecessors from the latter.
    const Costs recomputed = keep_costs ? Costs{} : walk_costs(g, targets[order[k]]);
    const std::vector<int>& previous = keep_costs ? costs[order[k]].previous : recomputed.previous;
    std::vector<int> cells;
    for (int c = targets[order[k + 1]]; c >= 0; c = previous[c]) cells.push_back(c);
    std::reverse(cells.begin(), cells.end());
    if (cells.size() < 2) continue;
    for (const auto& p : shortcut(g, cells))
      if (lap.empty() || (p - lap.back()).norm() > 1e-9) lap.push_back(p);
  }
  std::vector<Eigen::Vector2d> route;
  for (int l = 0; l < std::max(1, options.laps); ++l)
    for (const auto& p : lap)
      if (route.empty() || (p - route.back()).norm() > 1e-9) route.push_back(p);
  for (auto& p : route) p = (p * 1000).array().round() / 1000;  // millimetres in the scene file
  return route;
}

}  // namespace wifislam::floorplan
