#include "floorplan/route_planner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <queue>
#include <unordered_map>

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

std::vector<cv::Point> to_pixels(const sim::world::Polygon2& ring, const Grid& g) {
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
// Targets times piece cells at most for exact walk costs between every two targets (a few
// seconds); see plan_tour.
constexpr double kMaxExactWalkCells = 2e7;

Grid make_grid(const sim::world::FloorPlan& plan, const TourOptions& options) {
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
  const sim::world::WallFaceGrid faces(plan, reach_m);
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
  CV_Assert(g.piece.isContinuous() && g.clearance_m.isContinuous());  // read by cell index
  return g;
}

/// Walking costs from `source` to every cell of the piece (Dijkstra, 8-neighbours), with the
/// predecessor of each cell. A step costs its length times (1 + 0.5 m / clearance): the middle of
/// a corridor is cheaper than its sides.
struct Costs {
  std::vector<double> cost;
  std::vector<int> previous;
};

constexpr int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1}, kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};

/// Calls step(j, cost) for each neighbour j of cell i that is in the piece, in direction order
/// (kDx, kDy), with the cost of the step from i into j. The walks' inner loop (every target's
/// Dijkstra visits the whole piece): cell i's row and column are found once, and the rasters
/// (continuous, made by OpenCV's arithmetic) are read by cell index.
template <class Step>
void for_each_step(const Grid& g, int i, Step&& step) {
  const int x = i % g.width, y = i / g.width;
  const int* piece = g.piece.ptr<int>();
  const float* clearance_m = g.clearance_m.ptr<float>();
  for (int k = 0; k < 8; ++k) {
    const int nx = x + kDx[k], ny = y + kDy[k];
    if (nx < 0 || ny < 0 || nx >= g.width || ny >= g.height) continue;
    const int j = ny * g.width + nx;
    if (!piece[j]) continue;
    const double length_m = (k < 4 ? 1.0 : M_SQRT2) * g.cell_m;
    step(j, length_m * (1.0 + 0.5 / std::max(0.05f, clearance_m[j])));
  }
}

Costs walk_costs(const Grid& g, int source) {
  const int n = g.width * g.height;
  Costs c{std::vector<double>(n, std::numeric_limits<double>::infinity()), std::vector<int>(n, -1)};
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  c.cost[source] = 0;
  open.push({0.0, source});
  while (!open.empty()) {
    const auto [cost, i] = open.top();
    open.pop();
    if (cost > c.cost[i]) continue;
    for_each_step(g, i, [&, cost = cost, i = i](int j, double step) {
      const double next = cost + step;
      if (next < c.cost[j]) {
        c.cost[j] = next;
        c.previous[j] = i;
        open.push({next, j});
      }
    });
  }
  return c;
}

/// The same Dijkstra as walk_costs, stopped early: for large plans, where every target's costs
/// over the whole piece would make the route quadratic in the plan's size. Its arrays are reused
/// between runs (only the cells a run touched are reset), and up to where it stops it settles
/// cells in walk_costs' order with walk_costs' costs and predecessors.
class BoundedWalk {
 public:
  explicit BoundedWalk(const Grid& g)
      : g_(g),
        cost_(static_cast<std::size_t>(g.width) * g.height,
              std::numeric_limits<double>::infinity()),
        previous_(cost_.size(), -1) {}

  /// Runs from `source`; `settled(cell, cost)` is called for each cell as it is settled, in
  /// order of cost, and returns false to stop.
  template <class Settled>
  void run(int source, Settled&& settled) {
    for (const int i : touched_)
      cost_[i] = std::numeric_limits<double>::infinity(), previous_[i] = -1;
    touched_.clear();
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
    cost_[source] = 0;
    touched_.push_back(source);
    open.push({0.0, source});
    while (!open.empty()) {
      const auto [cost, i] = open.top();
      open.pop();
      if (cost > cost_[i]) continue;
      if (!settled(i, cost)) return;
      for_each_step(g_, i, [&, cost = cost, i = i](int j, double step) {
        const double next = cost + step;
        if (next < cost_[j]) {
          if (std::isinf(cost_[j])) touched_.push_back(j);
          cost_[j] = next;
          previous_[j] = i;
          open.push({next, j});
        }
      });
    }
  }
  /// The predecessor of a cell the last run settled.
  int previous(int cell) const { return previous_[cell]; }

 private:
  const Grid& g_;
  std::vector<double> cost_;
  std::vector<int> previous_;
  std::vector<int> touched_;
};

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
///
/// Each new target can only lower the distances of cells nearer to it than the largest distance
/// so far (the new target's own), so only the cells in that square around it are updated, and
/// the farthest cell is found from per-block maxima. The targets are those of the plain scan over
/// every cell for every target (the same distances, the first farthest cell in row order), at a
/// cost that stays near linear in the plan's size.
std::vector<int> spread_targets(const Grid& g, double spacing_m, std::vector<int> targets) {
  std::vector<int> cells;
  std::vector<std::size_t> row_begin(g.height + 1, 0);  // cells of row y: [row_begin[y], [y+1])
  int start = -1;
  for (int i = 0; i < g.width * g.height; ++i) {
    if (!g.piece(i / g.width, i % g.width)) continue;
    cells.push_back(i);
    ++row_begin[i / g.width + 1];
    if (start < 0 || g.clearance(i) > g.clearance(start)) start = i;
  }
  for (int y = 0; y < g.height; ++y) row_begin[y + 1] += row_begin[y];
  if (targets.empty()) targets.push_back(start);

  constexpr std::size_t kBlock = 256;
  std::vector<double> nearest(cells.size(), 1e300);
  std::vector<double> block_max((cells.size() + kBlock - 1) / kBlock, 1e300);
  // Lowers the distances of the cells within `radius_m` (a square) of target cell t.
  auto update = [&](int t, double radius_m) {
    const Eigen::Vector2d tc = g.centre_of(t);
    const int r = radius_m >= 1e299 ? std::max(g.width, g.height)
                                    : static_cast<int>(std::ceil(radius_m / g.cell_m)) + 1;
    const int tx = t % g.width, ty = t / g.width;
    const int y0 = std::max(0, ty - r), y1 = std::min(g.height - 1, ty + r);
    const int x0 = tx - r, x1 = tx + r;
    for (int y = y0; y <= y1; ++y) {
      auto first = std::lower_bound(cells.begin() + row_begin[y], cells.begin() + row_begin[y + 1],
                                    y * g.width + std::max(0, x0));
      const int last_cell = y * g.width + std::min(g.width - 1, x1);
      std::size_t k = first - cells.begin();
      if (k >= row_begin[y + 1] || cells[k] > last_cell) continue;
      const std::size_t k_begin = k;
      for (; k < row_begin[y + 1] && cells[k] <= last_cell; ++k)
        nearest[k] = std::min(nearest[k], (g.centre_of(cells[k]) - tc).norm());
      for (std::size_t b = k_begin / kBlock; b * kBlock < k; ++b) {
        const auto from = nearest.begin() + static_cast<long>(b * kBlock);
        const auto to =
            nearest.begin() + static_cast<long>(std::min(cells.size(), (b + 1) * kBlock));
        block_max[b] = *std::max_element(from, to);
      }
    }
  };
  for (std::size_t t = 0; t + 1 < targets.size(); ++t) update(targets[t], 1e300);
  double largest = *std::max_element(block_max.begin(), block_max.end());
  while (true) {
    update(targets.back(), largest);
    largest = *std::max_element(block_max.begin(), block_max.end());
    const std::size_t block =
        std::find(block_max.begin(), block_max.end(), largest) - block_max.begin();
    const std::size_t far =
        std::find(nearest.begin() + static_cast<long>(block * kBlock), nearest.end(), largest) -
        nearest.begin();
    if (largest < spacing_m) break;
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

/// Walking costs between the targets (d[a][b] from a to b), and the cells of the walk between
/// any two.
class TargetWalks {
 public:
  virtual ~TargetWalks() = default;
  const std::vector<std::vector<double>>& distances() const { return d_; }
  /// The cells of the cheapest walk from target a to target b, a's cell first.
  virtual std::vector<int> leg(int a, int b) = 0;

 protected:
  std::vector<std::vector<double>> d_;
};

/// Every target's walk costs over the whole piece: exact, and quadratic in the plan's size. The
/// costs are kept for the legs when they fit in ~0.5 GB; else (hundreds of targets over millions
/// of cells) each leg's are computed again, the same numbers, so the route is the same either way.
class ExactWalks final : public TargetWalks {
 public:
  ExactWalks(const Grid& g, const std::vector<int>& targets) : g_(g), targets_(targets) {
    keep_costs_ = static_cast<double>(targets.size()) * g.width * g.height <= kMaxKeptCostCells;
    d_.assign(targets.size(), std::vector<double>(targets.size()));
    for (std::size_t a = 0; a < targets.size(); ++a) {
      Costs from_a = walk_costs(g, targets[a]);
      for (std::size_t b = 0; b < targets.size(); ++b) d_[a][b] = from_a.cost[targets[b]];
      if (keep_costs_) costs_.push_back(std::move(from_a));
    }
  }
  std::vector<int> leg(int a, int b) override {
    const Costs recomputed = keep_costs_ ? Costs{} : walk_costs(g_, targets_[a]);
    const std::vector<int>& previous = keep_costs_ ? costs_[a].previous : recomputed.previous;
    std::vector<int> cells;
    for (int c = targets_[b]; c >= 0; c = previous[c]) cells.push_back(c);
    std::reverse(cells.begin(), cells.end());
    return cells;
  }

 private:
  const Grid& g_;
  const std::vector<int>& targets_;
  bool keep_costs_ = false;
  std::vector<Costs> costs_;
};

/// For each cell of the piece, the target that reaches it first (one Dijkstra from all targets at
/// once), -1 outside the piece: the walking-distance Voronoi regions of the targets.
std::vector<int> nearest_target_labels(const Grid& g, const std::vector<int>& targets) {
  const std::size_t n = static_cast<std::size_t>(g.width) * g.height;
  std::vector<double> cost(n, std::numeric_limits<double>::infinity());
  std::vector<int> label(n, -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  for (std::size_t t = 0; t < targets.size(); ++t)
    if (label[targets[t]] < 0) {
      cost[targets[t]] = 0;
      label[targets[t]] = static_cast<int>(t);
      open.push({0.0, targets[t]});
    }
  while (!open.empty()) {
    const auto [c, i] = open.top();
    open.pop();
    if (c > cost[i]) continue;
    for_each_step(g, i, [&, c = c, i = i](int j, double step) {
      const double next = c + step;
      if (next < cost[j]) cost[j] = next, label[j] = label[i], open.push({next, j});
    });
  }
  return label;
}

/// Walk costs between neighbouring targets only, and the rest along the graph they make: near
/// linear in the plan's size. From each target, the Dijkstra of walk_costs runs until it has
/// settled every target whose Voronoi region touches its own and has gone `radius` (cost) far;
/// the costs to the targets it settled are exact. A cost between targets farther apart is that of
/// the cheapest chain of such walks, at least the exact one and close to it where targets are
/// dense (every cell within the target spacing of one). The graph is connected because the
/// Voronoi regions of a connected piece are.
class SparseWalks final : public TargetWalks {
 public:
  SparseWalks(const Grid& g, const std::vector<int>& targets, double radius)
      : targets_(targets), walk_(g) {
    const std::size_t n = targets.size();
    std::unordered_map<int, std::vector<int>> targets_at;  // a cell's targets (a route may repeat)
    for (std::size_t t = 0; t < n; ++t) targets_at[targets[t]].push_back(static_cast<int>(t));
    const std::vector<int> label = nearest_target_labels(g, targets);
    std::vector<std::vector<int>> touching(n);  // by label
    for (int i = 0; i < g.width * g.height; ++i) {
      if (label[i] < 0) continue;
      for_each_step(g, i, [&](int j, double) {
        if (label[j] != label[i]) touching[label[i]].push_back(label[j]);
      });
    }
    for (auto& t : touching)
      std::sort(t.begin(), t.end()), t.erase(std::unique(t.begin(), t.end()), t.end());

    std::vector<std::vector<std::pair<int, double>>> edges(n);
    std::vector<char> wanted(n, 0);
    for (std::size_t a = 0; a < n; ++a) {
      std::size_t missing = 0;
      for (const int b : touching[label[targets[a]]]) missing += !wanted[b], wanted[b] = 1;
      walk_.run(targets[a], [&](int cell, double cost) {
        const auto it = targets_at.find(cell);
        if (it != targets_at.end())
          for (const int b : it->second) {
            if (b != static_cast<int>(a)) edges[a].push_back({b, cost});
            if (wanted[b]) wanted[b] = 0, --missing;
          }
        return missing > 0 || cost <= radius;
      });
      for (const int b : touching[label[targets[a]]]) wanted[b] = 0;
    }
    // Cheapest chains: Dijkstra over the target graph from each target.
    d_.assign(n, std::vector<double>(n, std::numeric_limits<double>::infinity()));
    via_.assign(n, std::vector<int>(n, -1));
    using Item = std::pair<double, int>;
    for (std::size_t a = 0; a < n; ++a) {
      std::vector<double>& d = d_[a];
      std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
      d[a] = 0;
      open.push({0.0, static_cast<int>(a)});
      while (!open.empty()) {
        const auto [c, u] = open.top();
        open.pop();
        if (c > d[u]) continue;
        for (const auto& [v, w] : edges[u])
          if (c + w < d[v]) d[v] = c + w, via_[a][v] = u, open.push({c + w, v});
      }
    }
  }
  std::vector<int> leg(int a, int b) override {
    std::vector<int> hops{b};  // targets from b back to a
    while (hops.back() != a && via_[a][hops.back()] >= 0) hops.push_back(via_[a][hops.back()]);
    std::reverse(hops.begin(), hops.end());
    std::vector<int> cells{targets_[a]};
    for (std::size_t h = 0; h + 1 < hops.size(); ++h) {
      const int from = targets_[hops[h]], to = targets_[hops[h + 1]];
      walk_.run(from, [&](int cell, double) { return cell != to; });
      std::vector<int> piece;
      for (int c = to; c != from; c = walk_.previous(c)) piece.push_back(c);
      cells.insert(cells.end(), piece.rbegin(), piece.rend());
    }
    return cells;
  }

 private:
  const std::vector<int>& targets_;
  BoundedWalk walk_;
  std::vector<std::vector<int>> via_;  // via_[a][b]: the target before b on the chain from a
};

}  // namespace

std::vector<Eigen::Vector2d> plan_tour(const sim::world::FloorPlan& plan,
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
  // Exact walk costs between all targets while that stays cheap (every plan we ship, and any
  // building up to a few hundred rooms); past that, the sparse graph of neighbouring targets.
  const double piece_cells = cv::countNonZero(g.piece);
  std::unique_ptr<TargetWalks> walks;
  if (static_cast<double>(targets.size()) * piece_cells <= kMaxExactWalkCells)
    walks = std::make_unique<ExactWalks>(g, targets);
  else
    walks = std::make_unique<SparseWalks>(g, targets, 2 * options.target_spacing_m);
  std::vector<int> order(targets.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  if (!given) order = tour_order(walks->distances());
  order.push_back(order.front());  // a closed loop: the start is seen again

  std::vector<Eigen::Vector2d> lap;
  for (std::size_t k = 0; k + 1 < order.size(); ++k) {
    const std::vector<int> cells = walks->leg(order[k], order[k + 1]);
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
