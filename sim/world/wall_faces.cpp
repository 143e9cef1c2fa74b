#include "sim/world/wall_faces.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <tuple>

#include "core/rng.hpp"
#include "sim/world/plan_queries.hpp"

namespace wifislam::sim {

namespace {

struct Piece {
  Eigen::Vector2d a, b;
  int solid = -1;
  int door = -1;
  double length() const { return (b - a).norm(); }
  Eigen::Vector2d dir() const { return (b - a).normalized(); }
  Eigen::Vector2d left_normal() const {
    const Eigen::Vector2d d = dir();
    return {-d.y(), d.x()};
  }
  Eigen::Vector2d mid() const { return 0.5 * (a + b); }
};

constexpr double kTol = 1e-6;

/// Cuts `p` at the given distances from p.a (those strictly inside), sharing each cut point
/// between the two pieces it separates.
void split_at(const Piece& p, std::vector<double> cuts, std::vector<Piece>& out) {
  const double len = p.length();
  std::sort(cuts.begin(), cuts.end());
  Eigen::Vector2d start = p.a;
  double last = 0;
  for (double c : cuts) {
    if (c <= last + kTol || c >= len - kTol) continue;
    const Eigen::Vector2d cut = p.a + (p.b - p.a) * (c / len);
    Piece q = p;
    q.a = start;
    q.b = cut;
    out.push_back(q);
    start = cut;
    last = c;
  }
  Piece q = p;
  q.a = start;
  out.push_back(q);
}

bool is_convex_block(const PolygonWithHoles2& solid) {
  if (!solid.holes.empty()) return false;
  const Polygon2& r = solid.outer;
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    const Eigen::Vector2d e0 = r[(i + 1) % n] - r[i];
    const Eigen::Vector2d e1 = r[(i + 2) % n] - r[(i + 1) % n];
    if (e0.x() * e1.y() - e0.y() * e1.x() < 0) return false;
  }
  return true;
}

/// When q faces p across a wall at most `max_gap_m` thick, the interval of p (distances from p.a)
/// that q covers; else an empty optional.
std::optional<std::pair<double, double>> opposite_interval(const Piece& p, const Piece& q,
                                                           double max_gap_m) {
  const Eigen::Vector2d dp = p.dir(), dq = q.dir();
  if (dp.dot(dq) > -1 + 1e-9) return std::nullopt;
  const Eigen::Vector2d right(dp.y(), -dp.x());
  const double gap_a = (q.a - p.a).dot(right), gap_b = (q.b - p.a).dot(right);
  if (std::abs(gap_a - gap_b) > kTol || gap_a <= kTol || gap_a > max_gap_m + kTol)
    return std::nullopt;
  const double sa = (q.a - p.a).dot(dp), sb = (q.b - p.a).dot(dp);
  const double lo = std::max(0.0, std::min(sa, sb)), hi = std::min(p.length(), std::max(sa, sb));
  if (hi - lo <= kTol) return std::nullopt;
  return std::make_pair(std::min(sa, sb), std::max(sa, sb));
}

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

/// What bounds a face on its free side, ranked: rooms win over corridors over open areas.
struct Bounding {
  int rank = 0;  // 3 room, 2 corridor, 1 open area, 0 nothing (outside)
  WallMaterial material = WallMaterial::kPlasterboard;
};

Bounding bounding_of(const Eigen::Vector2d& p, const Scene& scene, const PlanLayout& layout,
                     const FloorPlan& plan) {
  for (const Door& d : plan.doors) {
    if (!d.open) continue;
    const Eigen::Vector2d f = p - d.center_m;
    const Eigen::Vector2d n(-d.along_wall.y(), d.along_wall.x());
    if (std::abs(f.dot(d.along_wall)) <= 0.5 * d.width_m + kTol &&
        std::abs(f.dot(n)) <= 0.5 * d.wall_thickness_m + kTol)
      return {3, plan.rooms[d.room_index].material};
  }
  for (const Room& r : plan.rooms)
    if (ring_contains(r.polygon_m, p)) return {3, r.material};
  for (const CorridorLayout& c : layout.corridors)
    if (c.rect.contains(p)) return {2, scene.corridors[c.corridor_index].material};
  for (const OpenArea& a : scene.open_areas)
    if (ring_contains(a.polygon_m, p)) return {1, a.material};
  return {};
}

}  // namespace

void build_wall_faces(const Scene& scene, const PlanLayout& layout, FloorPlan& plan) {
  const double t = scene.building.wall_thickness_m;

  // 1. Boundary edges, wall on the right (rings have the wall on their left).
  std::vector<Piece> pieces;
  for (std::size_t s = 0; s < plan.walls.size(); ++s) {
    auto add_ring = [&](const Polygon2& ring) {
      for (std::size_t i = 0, n = ring.size(); i < n; ++i)
        pieces.push_back({ring[(i + 1) % n], ring[i], static_cast<int>(s), -1});
    };
    add_ring(plan.walls[s].outer);
    for (const auto& h : plan.walls[s].holes) add_ring(h);
  }

  // 2. Closed doors: cut both faces of the wall at the door's edges.
  for (std::size_t d = 0; d < plan.doors.size(); ++d) {
    const Door& door = plan.doors[d];
    if (door.open) continue;
    const Eigen::Vector2d u = door.along_wall, n(-u.y(), u.x());
    const double hw = 0.5 * door.width_m, ht = 0.5 * door.wall_thickness_m;
    std::vector<Piece> next;
    for (const Piece& p : pieces) {
      const Eigen::Vector2d fa = p.a - door.center_m, fb = p.b - door.center_m;
      const double la = fa.dot(n), lb = fb.dot(n), sa = fa.dot(u), sb = fb.dot(u);
      const bool on_face_line = std::abs(la - lb) < kTol && std::abs(std::abs(la) - ht) < kTol;
      if (!on_face_line || std::min(sa, sb) >= hw - kTol || std::max(sa, sb) <= -hw + kTol) {
        next.push_back(p);
        continue;
      }
      // Distances from p.a of the door edges, then mark the piece inside the opening.
      const double sign = sb > sa ? 1.0 : -1.0;
      const std::size_t first = next.size();
      split_at(p, {(-hw - sa) * sign, (hw - sa) * sign}, next);
      for (std::size_t k = first; k < next.size(); ++k) {
        const double s_mid = (next[k].mid() - door.center_m).dot(u);
        if (std::abs(s_mid) < hw) next[k].door = static_cast<int>(d);
      }
    }
    pieces = std::move(next);
  }

  // 3. Cut faces at the ends of the faces opposite them across a wall.
  const double max_gap_m = 2 * t;
  {
    std::vector<Piece> next;
    for (const Piece& p : pieces) {
      std::vector<double> cuts;
      for (const Piece& q : pieces) {
        if (&q == &p) continue;
        if (auto iv = opposite_interval(p, q, max_gap_m)) {
          cuts.push_back(iv->first);
          cuts.push_back(iv->second);
        }
      }
      split_at(p, cuts, next);
    }
    pieces = std::move(next);
  }

  // 4. Pair opposite faces into walls; convex blocks are one wall.
  UnionFind walls(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    for (std::size_t j = i + 1; j < pieces.size(); ++j) {
      auto iv = opposite_interval(pieces[i], pieces[j], max_gap_m);
      if (iv && std::abs(iv->first) < 1e-5 && std::abs(iv->second - pieces[i].length()) < 1e-5)
        walls.unite(static_cast<int>(i), static_cast<int>(j));
    }
  }
  // A face with no opposite (the end of a wall at a door jamb, the outside of a building corner)
  // belongs to the wall it continues: a collinear neighbour's wall if there is one, else any
  // neighbour's that has two faces.
  {
    std::vector<int> group_size(pieces.size(), 0);
    for (std::size_t i = 0; i < pieces.size(); ++i) ++group_size[walls.find(static_cast<int>(i))];
    std::vector<std::pair<std::size_t, int>> merges;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      if (group_size[walls.find(static_cast<int>(i))] > 1 || pieces[i].door >= 0) continue;
      int collinear = -1, other = -1;
      for (std::size_t j = 0; j < pieces.size(); ++j) {
        if (j == i || group_size[walls.find(static_cast<int>(j))] < 2) continue;
        if (pieces[j].b != pieces[i].a && pieces[j].a != pieces[i].b) continue;
        if (pieces[j].dir().dot(pieces[i].dir()) > 1 - 1e-9) {
          if (collinear < 0) collinear = static_cast<int>(j);
        } else if (other < 0) {
          other = static_cast<int>(j);
        }
      }
      if (collinear >= 0 || other >= 0) merges.emplace_back(i, collinear >= 0 ? collinear : other);
    }
    for (const auto& [i, j] : merges) walls.unite(static_cast<int>(i), j);
  }
  std::vector<int> first_of_solid(plan.walls.size(), -1);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const int s = pieces[i].solid;
    if (!is_convex_block(plan.walls[s])) continue;
    if (first_of_solid[s] < 0)
      first_of_solid[s] = static_cast<int>(i);
    else
      walls.unite(first_of_solid[s], static_cast<int>(i));
  }

  // 5. Inside or outside, and what each wall bounds.
  std::vector<bool> exterior(pieces.size());
  std::vector<Bounding> group_bounding(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Eigen::Vector2d probe = pieces[i].mid() + 1e-4 * pieces[i].left_normal();
    exterior[i] = !regions_contain(plan.free_space, probe);
    if (exterior[i]) continue;
    const Bounding b = bounding_of(probe, scene, layout, plan);
    Bounding& g = group_bounding[walls.find(static_cast<int>(i))];
    if (b.rank > g.rank) g = b;
  }

  // 6. Compact wall ids in order of first appearance; cut into appearance segments.
  std::vector<int> wall_id(pieces.size(), -1);
  int next_id = 0;
  Rng rng = Rng::stream(scene.seed, "appearance/segments");
  const double segment_m = std::max(0.1, scene.appearance.segment_length_m);
  int next_variant = 1;
  // kPosition: the shared look of the k-th segment_m-long stretch of a wall, counted from the
  // wall's start in the direction of its faces (interior faces have free space on their left, so
  // two walls that are copies of each other under a rotation count the same way).
  const auto line_key = [&](std::size_t i) {
    const Eigen::Vector2d d = pieces[i].dir();
    return std::tuple<int, long, long>(walls.find(static_cast<int>(i)), std::lround(d.x() * 1e3),
                                       std::lround(d.y() * 1e3));
  };
  std::map<std::tuple<int, long, long>, std::pair<double, double>> line_extent;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (exterior[i]) continue;
    const double s = pieces[i].a.dot(pieces[i].dir());
    const double e = pieces[i].b.dot(pieces[i].dir());
    const auto [it, inserted] = line_extent.emplace(line_key(i), std::pair(s, e));
    it->second = {std::min(it->second.first, s), std::max(it->second.second, e)};
  }
  // Same position on a wall of the same length (to 0.1 m): same look. Keying by length too keeps
  // walls of different lengths (a rail and a rung) from aliasing with each other.
  std::map<std::pair<long, int>, int> variant_at_position;
  const auto shared_variant = [&](std::size_t piece, const Eigen::Vector2d& mid) {
    if (scene.appearance.aliasing_scope == AliasingScope::kSegment) return 0;
    const auto [start_m, end_m] = line_extent.at(line_key(piece));
    const int position =
        static_cast<int>(std::floor((mid.dot(pieces[piece].dir()) - start_m) / segment_m));
    const auto [it, inserted] =
        variant_at_position.emplace(std::pair(std::lround((end_m - start_m) * 10), position), 0);
    if (inserted) it->second = next_variant++;
    return it->second;
  };
  plan.wall_faces.clear();
  plan.appearance_segments.clear();
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Piece& p = pieces[i];
    const int root = walls.find(static_cast<int>(i));
    if (wall_id[root] < 0) wall_id[root] = next_id++;
    WallFace2 face;
    face.wall_id = wall_id[root];
    face.exterior = exterior[i];
    face.door_index = p.door;
    face.material = p.door >= 0 ? WallMaterial::kWoodDoor : group_bounding[root].material;
    if (exterior[i]) {
      face.a_m = p.a;
      face.b_m = p.b;
      plan.wall_faces.push_back(face);
      continue;
    }
    const int count = std::max(1, static_cast<int>(std::ceil(p.length() / segment_m - 1e-9)));
    Eigen::Vector2d start = p.a;
    for (int k = 0; k < count; ++k) {
      const Eigen::Vector2d end =
          k + 1 == count ? p.b : p.a + (p.b - p.a) * (double(k + 1) / count);
      AppearanceSegment segment;
      segment.variant = rng.bernoulli(scene.appearance.aliasing)
                            ? shared_variant(i, 0.5 * (start + end))
                            : next_variant++;
      face.appearance_segment = static_cast<int>(plan.appearance_segments.size());
      plan.appearance_segments.push_back(segment);
      face.a_m = start;
      face.b_m = end;
      plan.wall_faces.push_back(face);
      start = end;
    }
  }
  plan.wall_count = next_id;
}

}  // namespace wifislam::sim
