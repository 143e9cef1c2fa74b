#include "floorplan/imported_plan.hpp"

#include <algorithm>
#include <map>
#include <numeric>

#include <fmt/format.h>

#include "floorplan/obstacle_strips.hpp"

namespace wifislam::floorplan {

const char* to_string(PlanFormat format) {
  switch (format) {
    case PlanFormat::kOsmSit:
      return "osm-sit";
    case PlanFormat::kWrld:
      return "wrld";
    case PlanFormat::kImdf:
      return "imdf";
  }
  return "unknown";
}

namespace {

struct Groups {
  std::vector<int> parent;
  explicit Groups(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) { parent[find(a)] = find(b); }
};

double ring_area_m2(const Ring& r) {
  double a = 0;
  for (std::size_t i = 0, n = r.size(); i < n; ++i)
    a += r[i].x() * r[(i + 1) % n].y() - r[(i + 1) % n].x() * r[i].y();
  return 0.5 * a;
}

/// Walkable inputs outside the largest group joined by open doors are demoted to rooms.
std::vector<sim::scene::SpaceKind> connected_kinds(const std::vector<SpaceInput>& inputs,
                                                   const Partition& partition,
                                                   const std::vector<PlacedDoor>& doors,
                                                   std::vector<std::string>& notes) {
  std::vector<sim::scene::SpaceKind> kinds;
  for (const SpaceInput& in : inputs) kinds.push_back(in.kind);
  std::vector<int> pieces_of(inputs.size(), 0);
  std::vector<double> area(inputs.size(), 0.0);
  for (const SpacePiece& p : partition.pieces) {
    ++pieces_of[p.input];
    area[p.input] += std::abs(ring_area_m2(p.free_m.outer));
  }
  Groups groups(inputs.size());
  for (const PlacedDoor& d : doors)
    if (d.door.open && kinds[d.a] != sim::scene::SpaceKind::kRoom &&
        kinds[d.b] != sim::scene::SpaceKind::kRoom)
      groups.unite(d.a, d.b);
  std::map<int, double> group_area;
  for (std::size_t i = 0; i < inputs.size(); ++i)
    if (kinds[i] != sim::scene::SpaceKind::kRoom && pieces_of[i] == 1)
      group_area[groups.find(static_cast<int>(i))] += area[i];
  int best = -1;
  for (const auto& [root, a] : group_area)
    if (best < 0 || a > group_area[best]) best = root;
  int demoted = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (kinds[i] == sim::scene::SpaceKind::kRoom || pieces_of[i] == 0) continue;
    // A space split into pieces has no door between them: only a single piece can be walked.
    if (pieces_of[i] > 1 || groups.find(static_cast<int>(i)) != best) {
      kinds[i] = sim::scene::SpaceKind::kRoom;
      ++demoted;
    }
  }
  if (demoted > 0)
    notes.push_back(fmt::format(
        "{} corridor or area space(s) not joined to the largest walkable group by an open door "
        "(or split into pieces by the wall thickness) are rooms here: the robot's space is one "
        "piece",
        demoted));
  return kinds;
}

}  // namespace

void finish_plan(const GeosContext& geos, const std::vector<SpaceInput>& inputs,
                 const Partition& partition, const PartitionOptions& partition_options,
                 const std::vector<PlacedDoor>& doors, ImportedPlan& plan) {
  const int strips = make_cut_off_strips_solid(geos, partition, partition_options.min_area_m2,
                                               partition_options.wall_thickness_m, plan.obstacles);
  if (strips > 0)
    plan.notes.push_back(fmt::format(
        "{} strip(s) of free space under {:.1f} m^2 or narrower than a wall, cut off a space "
        "between an obstacle and its wall (the outline moved by the wall thickness), are part of "
        "that obstacle here",
        strips, partition_options.min_area_m2));
  const std::vector<sim::scene::SpaceKind> kinds =
      connected_kinds(inputs, partition, doors, plan.notes);
  std::vector<int> piece_number(inputs.size(), 0);
  for (const SpacePiece& p : partition.pieces) {
    const SpaceInput& in = inputs[p.input];
    sim::scene::Space space;
    const int k = piece_number[p.input]++;
    space.id = k == 0 ? in.id : fmt::format("{}-{}", in.id, k + 1);
    space.name = in.name;
    space.kind = kinds[p.input];
    space.material = in.material;
    space.polygon_m = p.free_m.outer;
    if (ring_area_m2(space.polygon_m) < 0)
      std::reverse(space.polygon_m.begin(), space.polygon_m.end());
    plan.spaces.push_back(std::move(space));
    for (const Ring& hole : p.free_m.holes) plan.obstacles.push_back({hole});
  }
  for (const PlacedDoor& d : doors) plan.doors.push_back(d.door);
  plan.counts.spaces = static_cast<int>(plan.spaces.size());
  plan.counts.space_doors = static_cast<int>(plan.doors.size());
  plan.counts.obstacles = static_cast<int>(plan.obstacles.size());
}

}  // namespace wifislam::floorplan
