#include "sim/world/wall_faces.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <tuple>

#include "core/rng.hpp"
#include "sim/world/box_grid.hpp"
#include "sim/world/plan_queries.hpp"
#include "sim/world/region_locator.hpp"

namespace wifislam::sim::world {

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
  radio_model::WallMaterial material = radio_model::WallMaterial::kPlasterboard;
};

template <class Points>
void add_box(BoxGrid& grid, int index, const Points& points, double margin_m = 1e-9) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = Eigen::Vector2d::Constant(-1e300);
  for (const Eigen::Vector2d& q : points) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  grid.add(index, lo - Eigen::Vector2d::Constant(margin_m),
           hi + Eigen::Vector2d::Constant(margin_m));
}

/// What bounds the points just off the faces: the open doors, rooms, corridors, spaces and open
/// areas near a point, found on grids of their boxes (a scan of all of them per face is quadratic
/// in the building's size), tried in the order and with the tests of a scan.
class BoundingLocator {
 public:
  BoundingLocator(const scene::Scene& scene, const PlanLayout& layout, const FloorPlan& plan)
      : scene_(scene), layout_(layout), plan_(plan) {
    for (std::size_t i = 0; i < plan.doors.size(); ++i) {
      const Door& d = plan.doors[i];
      const double reach = 0.5 * d.width_m + 0.5 * d.wall_thickness_m + 1e-3;
      doors_.add(static_cast<int>(i), d.center_m - Eigen::Vector2d::Constant(reach),
                 d.center_m + Eigen::Vector2d::Constant(reach));
    }
    for (std::size_t i = 0; i < plan.rooms.size(); ++i)
      add_box(rooms_, static_cast<int>(i), plan.rooms[i].polygon_m);
    for (std::size_t i = 0; i < layout.corridors.size(); ++i)
      add_box(corridors_, static_cast<int>(i), layout.corridors[i].rect.corners());
    for (std::size_t i = 0; i < scene.spaces.size(); ++i)
      add_box(spaces_, static_cast<int>(i), scene.spaces[i].polygon_m);
    for (std::size_t i = 0; i < scene.open_areas.size(); ++i)
      add_box(open_areas_, static_cast<int>(i), scene.open_areas[i].polygon_m);
  }

  Bounding at(const Eigen::Vector2d& p) const {
    for (const int i : doors_.at(p)) {
      const Door& d = plan_.doors[i];
      if (!d.open) continue;
      const Eigen::Vector2d f = p - d.center_m;
      const Eigen::Vector2d n(-d.along_wall.y(), d.along_wall.x());
      if (d.room_index >= 0 && std::abs(f.dot(d.along_wall)) <= 0.5 * d.width_m + kTol &&
          std::abs(f.dot(n)) <= 0.5 * d.wall_thickness_m + kTol)
        return {3, plan_.rooms[d.room_index].material};
    }
    for (const int i : rooms_.at(p))
      if (ring_contains(plan_.rooms[i].polygon_m, p)) return {3, plan_.rooms[i].material};
    for (const int i : corridors_.at(p)) {
      const CorridorLayout& c = layout_.corridors[i];
      if (c.rect.contains(p)) return {2, scene_.corridors[c.corridor_index].material};
    }
    const std::vector<int> spaces = spaces_.at(p);
    for (const int i : spaces) {
      const scene::Space& s = scene_.spaces[i];
      if (s.kind == scene::SpaceKind::kCorridor && ring_contains(s.polygon_m, p))
        return {2, s.material};
    }
    for (const int i : open_areas_.at(p))
      if (ring_contains(scene_.open_areas[i].polygon_m, p))
        return {1, scene_.open_areas[i].material};
    for (const int i : spaces) {
      const scene::Space& s = scene_.spaces[i];
      if (s.kind == scene::SpaceKind::kArea && ring_contains(s.polygon_m, p))
        return {1, s.material};
    }
    return {};
  }

 private:
  const scene::Scene& scene_;
  const PlanLayout& layout_;
  const FloorPlan& plan_;
  BoxGrid doors_{4.0}, rooms_{4.0}, corridors_{4.0}, spaces_{4.0}, open_areas_{4.0};
};

/// Step 1: every boundary edge of every wall solid, with the wall on its right (rings have the
/// wall on their left).
std::vector<Piece> boundary_pieces(const FloorPlan& plan) {
  std::vector<Piece> pieces;
  for (std::size_t s = 0; s < plan.walls.size(); ++s) {
    auto add_ring = [&](const Polygon2& ring) {
      for (std::size_t i = 0, n = ring.size(); i < n; ++i)
        pieces.push_back({ring[(i + 1) % n], ring[i], static_cast<int>(s), -1});
    };
    add_ring(plan.walls[s].outer);
    for (const auto& h : plan.walls[s].holes) add_ring(h);
  }
  return pieces;
}

/// Step 2 for one closed door: cuts both faces of its wall at the door's edges and marks the
/// pieces inside the opening as the door (index `door_index`).
std::vector<Piece> cut_at_closed_door(const std::vector<Piece>& pieces, const Door& door,
                                      int door_index) {
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
      if (std::abs(s_mid) < hw) next[k].door = door_index;
    }
  }
  return next;
}

/// Step 2: closed doors, one after the other (a later door cuts the pieces an earlier one made).
///
/// A door cuts only faces on its own face lines, and the pieces of a face stay on that face's line,
/// so each face is cut by the closed doors near it, in door order, on its own: the pieces, and
/// their order, of cutting every face at every door in turn, without a pass over all faces per
/// door (10 000 doors: quadratic).
void cut_at_closed_doors(const FloorPlan& plan, std::vector<Piece>& pieces) {
  BoxGrid doors(4.0);
  for (std::size_t d = 0; d < plan.doors.size(); ++d) {
    const Door& door = plan.doors[d];
    if (door.open) continue;
    const double reach = 0.5 * door.width_m + 0.5 * door.wall_thickness_m + 1e-3;
    doors.add(static_cast<int>(d), door.center_m - Eigen::Vector2d::Constant(reach),
              door.center_m + Eigen::Vector2d::Constant(reach));
  }
  std::vector<Piece> cut;
  for (const Piece& p : pieces) {
    std::vector<Piece> of_p{p};
    for (const int d : doors.near(p.a.cwiseMin(p.b), p.a.cwiseMax(p.b)))
      of_p = cut_at_closed_door(of_p, plan.doors[d], d);
    cut.insert(cut.end(), of_p.begin(), of_p.end());
  }
  pieces = std::move(cut);
}

/// The pieces on a grid, each under its box grown by `max_gap_m`: a face that faces p across a
/// wall at most that thick (opposite_interval) shares a cell with p's own box.
BoxGrid piece_grid(const std::vector<Piece>& pieces, double max_gap_m) {
  BoxGrid grid(std::max(1.0, 2 * max_gap_m));
  for (std::size_t i = 0; i < pieces.size(); ++i)
    add_box(grid, static_cast<int>(i), std::array{pieces[i].a, pieces[i].b}, max_gap_m + 1e-3);
  return grid;
}

std::vector<int> pieces_near(const BoxGrid& grid, const Piece& p) {
  return grid.near(p.a.cwiseMin(p.b), p.a.cwiseMax(p.b));
}

/// Step 3: cuts each face at the ends of the faces opposite it across a wall, so that opposite
/// faces end up the same length and can be paired.
std::vector<Piece> cut_at_opposite_ends(const std::vector<Piece>& pieces, double max_gap_m) {
  const BoxGrid grid = piece_grid(pieces, max_gap_m);
  std::vector<Piece> next;
  for (const Piece& p : pieces) {
    std::vector<double> cuts;
    for (const int j : pieces_near(grid, p)) {
      const Piece& q = pieces[j];
      if (&q == &p) continue;
      if (auto iv = opposite_interval(p, q, max_gap_m)) {
        cuts.push_back(iv->first);
        cuts.push_back(iv->second);
      }
    }
    split_at(p, cuts, next);
  }
  return next;
}

/// Step 4a: two faces that cover each other exactly across a wall are one wall.
void unite_opposite_faces(const std::vector<Piece>& pieces, double max_gap_m, UnionFind& walls) {
  const BoxGrid grid = piece_grid(pieces, max_gap_m);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    for (const int near : pieces_near(grid, pieces[i])) {
      const std::size_t j = static_cast<std::size_t>(near);
      if (j <= i) continue;
      auto iv = opposite_interval(pieces[i], pieces[j], max_gap_m);
      if (iv && std::abs(iv->first) < 1e-5 && std::abs(iv->second - pieces[i].length()) < 1e-5)
        walls.unite(static_cast<int>(i), static_cast<int>(j));
    }
  }
}

/// The face that lone face `i` continues: a collinear neighbour in a wall of two or more faces
/// if there is one, else any such neighbour; -1 when none touches it.
int continued_face(const std::vector<Piece>& pieces, std::size_t i,
                   const std::vector<int>& group_size, UnionFind& walls,
                   const std::vector<int>& touching) {
  int collinear = -1, other = -1;
  for (const int near : touching) {
    const std::size_t j = static_cast<std::size_t>(near);
    if (j == i || group_size[walls.find(static_cast<int>(j))] < 2) continue;
    if (pieces[j].b != pieces[i].a && pieces[j].a != pieces[i].b) continue;
    if (pieces[j].dir().dot(pieces[i].dir()) > 1 - 1e-9) {
      if (collinear < 0) collinear = static_cast<int>(j);
    } else if (other < 0) {
      other = static_cast<int>(j);
    }
  }
  return collinear >= 0 ? collinear : other;
}

/// Step 4b: a face with no opposite (the end of a wall at a door jamb, the outside of a building
/// corner) belongs to the wall it continues. Merges are collected first so that they all see the
/// walls as step 4a left them.
void attach_lone_faces(const std::vector<Piece>& pieces, UnionFind& walls) {
  // The faces that end where a face starts, and start where it ends (exact points, as the
  // comparison in continued_face).
  const auto key = [](const Eigen::Vector2d& q) { return std::pair(q.x() + 0.0, q.y() + 0.0); };
  std::map<std::pair<double, double>, std::vector<int>> ending_at, starting_at;
  for (std::size_t j = 0; j < pieces.size(); ++j) {
    ending_at[key(pieces[j].b)].push_back(static_cast<int>(j));
    starting_at[key(pieces[j].a)].push_back(static_cast<int>(j));
  }
  std::vector<int> group_size(pieces.size(), 0);
  for (std::size_t i = 0; i < pieces.size(); ++i) ++group_size[walls.find(static_cast<int>(i))];
  std::vector<std::pair<std::size_t, int>> merges;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (group_size[walls.find(static_cast<int>(i))] > 1 || pieces[i].door >= 0) continue;
    std::vector<int> touching;
    if (const auto it = ending_at.find(key(pieces[i].a)); it != ending_at.end())
      touching = it->second;
    if (const auto it = starting_at.find(key(pieces[i].b)); it != starting_at.end())
      touching.insert(touching.end(), it->second.begin(), it->second.end());
    std::sort(touching.begin(), touching.end());
    touching.erase(std::unique(touching.begin(), touching.end()), touching.end());
    const int continued = continued_face(pieces, i, group_size, walls, touching);
    if (continued >= 0) merges.emplace_back(i, continued);
  }
  for (const auto& [i, j] : merges) walls.unite(static_cast<int>(i), j);
}

/// Step 4c: every face of a convex wall solid (a pillar) is one wall.
void unite_convex_blocks(const FloorPlan& plan, const std::vector<Piece>& pieces,
                         UnionFind& walls) {
  std::vector<int> first_of_solid(plan.walls.size(), -1);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const int s = pieces[i].solid;
    if (!is_convex_block(plan.walls[s])) continue;
    if (first_of_solid[s] < 0)
      first_of_solid[s] = static_cast<int>(i);
    else
      walls.unite(first_of_solid[s], static_cast<int>(i));
  }
}

/// Step 5's answer: which faces are outside, and for each wall (indexed by its union-find root)
/// the highest-ranked space one of its inside faces bounds.
struct FaceSides {
  std::vector<bool> exterior;
  std::vector<Bounding> wall_bounding;
};

/// Step 5: probes just off each face's free side.
FaceSides classify_face_sides(const scene::Scene& scene, const PlanLayout& layout,
                              const FloorPlan& plan, const std::vector<Piece>& pieces,
                              UnionFind& walls) {
  FaceSides sides{std::vector<bool>(pieces.size()), std::vector<Bounding>(pieces.size())};
  const RegionLocator free_space(plan.free_space);
  const BoundingLocator bounding(scene, layout, plan);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Eigen::Vector2d probe = pieces[i].mid() + 1e-4 * pieces[i].left_normal();
    sides.exterior[i] = free_space.find(probe) < 0;
    if (sides.exterior[i]) continue;
    const Bounding b = bounding.at(probe);
    Bounding& g = sides.wall_bounding[walls.find(static_cast<int>(i))];
    if (b.rank > g.rank) g = b;
  }
  return sides;
}

/// A straight line of one wall: its root and its direction (to 1e-3).
using LineKey = std::tuple<int, long, long>;

LineKey line_key(const std::vector<Piece>& pieces, std::size_t i, UnionFind& walls) {
  const Eigen::Vector2d d = pieces[i].dir();
  return LineKey(walls.find(static_cast<int>(i)), std::lround(d.x() * 1e3),
                 std::lround(d.y() * 1e3));
}

/// Extent of each inside wall line, in distances along its direction, so that kPosition can count
/// segments from the wall's start in the direction of its faces (interior faces have free space
/// on their left, so two walls that are copies of each other under a rotation count the same way).
std::map<LineKey, std::pair<double, double>> interior_line_extents(
    const std::vector<Piece>& pieces, const std::vector<bool>& exterior, UnionFind& walls) {
  std::map<LineKey, std::pair<double, double>> line_extent;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (exterior[i]) continue;
    const double s = pieces[i].a.dot(pieces[i].dir());
    const double e = pieces[i].b.dot(pieces[i].dir());
    const auto [it, inserted] = line_extent.emplace(line_key(pieces, i, walls), std::pair(s, e));
    it->second = {std::min(it->second.first, s), std::max(it->second.second, e)};
  }
  return line_extent;
}

/// Hands out the look (variant) of each appearance segment, in face order: with probability
/// `aliasing` a shared one, else a fresh one. All draws come from one stream, in segment order.
class SegmentVariants {
 public:
  /// `exterior` says which faces are outside (they get no segments).
  SegmentVariants(const scene::Scene& scene, const std::vector<Piece>& pieces,
                  const std::vector<bool>& exterior, UnionFind& walls, double segment_m)
      : scene_(scene),
        pieces_(pieces),
        walls_(walls),
        segment_m_(segment_m),
        rng_(Rng::stream(scene.seed, "appearance/segments")),
        line_extent_(interior_line_extents(pieces, exterior, walls)) {}

  /// The variant of the segment of face `piece` centred at `mid`.
  int next(std::size_t piece, const Eigen::Vector2d& mid) {
    return rng_.bernoulli(scene_.appearance.aliasing) ? shared(piece, mid) : next_variant_++;
  }

 private:
  /// kSegment: variant 0 everywhere. kPosition: same position on a wall of the same length (to
  /// 0.1 m), same look; keying by length too keeps walls of different lengths (a rail and a rung)
  /// from aliasing with each other.
  int shared(std::size_t piece, const Eigen::Vector2d& mid) {
    if (scene_.appearance.aliasing_scope == scene::AliasingScope::kSegment) return 0;
    const auto [start_m, end_m] = line_extent_.at(line_key(pieces_, piece, walls_));
    const int position =
        static_cast<int>(std::floor((mid.dot(pieces_[piece].dir()) - start_m) / segment_m_));
    const auto [it, inserted] =
        variant_at_position_.emplace(std::pair(std::lround((end_m - start_m) * 10), position), 0);
    if (inserted) it->second = next_variant_++;
    return it->second;
  }

  const scene::Scene& scene_;
  const std::vector<Piece>& pieces_;
  UnionFind& walls_;
  double segment_m_;
  Rng rng_;
  int next_variant_ = 1;
  std::map<LineKey, std::pair<double, double>> line_extent_;
  std::map<std::pair<long, int>, int> variant_at_position_;
};

/// Step 6 for one inside face: cuts it into equal appearance segments of at most segment_m, each
/// its own face. `face` holds what the segments share (wall, material, door); each gets its own
/// ends and appearance segment.
void add_segmented_face(const Piece& p, std::size_t piece, WallFace2& face, double segment_m,
                        SegmentVariants& variants, FloorPlan& plan) {
  const int count = std::max(1, static_cast<int>(std::ceil(p.length() / segment_m - 1e-9)));
  Eigen::Vector2d start = p.a;
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector2d end = k + 1 == count ? p.b : p.a + (p.b - p.a) * (double(k + 1) / count);
    AppearanceSegment segment;
    segment.variant = variants.next(piece, 0.5 * (start + end));
    face.appearance_segment = static_cast<int>(plan.appearance_segments.size());
    plan.appearance_segments.push_back(segment);
    face.a_m = start;
    face.b_m = end;
    plan.wall_faces.push_back(face);
    start = end;
  }
}

/// Step 6: compact wall ids in order of first appearance; inside faces cut into appearance
/// segments, outside faces whole.
void add_wall_faces(const std::vector<Piece>& pieces, const FaceSides& sides, double segment_m,
                    UnionFind& walls, SegmentVariants& variants, FloorPlan& plan) {
  std::vector<int> wall_id(pieces.size(), -1);
  int next_id = 0;
  plan.wall_faces.clear();
  plan.appearance_segments.clear();
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Piece& p = pieces[i];
    const int root = walls.find(static_cast<int>(i));
    if (wall_id[root] < 0) wall_id[root] = next_id++;
    WallFace2 face;
    face.wall_id = wall_id[root];
    face.exterior = sides.exterior[i];
    face.door_index = p.door;
    face.material =
        p.door >= 0 ? radio_model::WallMaterial::kWoodDoor : sides.wall_bounding[root].material;
    if (sides.exterior[i]) {
      face.a_m = p.a;
      face.b_m = p.b;
      plan.wall_faces.push_back(face);
      continue;
    }
    add_segmented_face(p, i, face, segment_m, variants, plan);
  }
  plan.wall_count = next_id;
}

}  // namespace

void build_wall_faces(const scene::Scene& scene, const PlanLayout& layout, FloorPlan& plan) {
  // Faces at most two wall thicknesses apart face each other across one wall.
  const double max_gap_m = 2 * scene.building.wall_thickness_m;
  std::vector<Piece> pieces = boundary_pieces(plan);
  cut_at_closed_doors(plan, pieces);
  pieces = cut_at_opposite_ends(pieces, max_gap_m);

  UnionFind walls(pieces.size());
  unite_opposite_faces(pieces, max_gap_m, walls);
  attach_lone_faces(pieces, walls);
  unite_convex_blocks(plan, pieces, walls);

  const FaceSides sides = classify_face_sides(scene, layout, plan, pieces, walls);
  const double segment_m = std::max(0.1, scene.appearance.segment_length_m);
  SegmentVariants variants(scene, pieces, sides.exterior, walls, segment_m);
  add_wall_faces(pieces, sides, segment_m, walls, variants, plan);
}

}  // namespace wifislam::sim::world
