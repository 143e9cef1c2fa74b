// OpenStreetMap Simple Indoor Tagging (https://wiki.openstreetmap.org/wiki/Simple_Indoor_Tagging):
// indoor=room|corridor|area polygons with level=*, no walls of their own. Walls are where spaces
// meet (space_partition.hpp); doors are inferred because few indoor maps carry door nodes:
//   a room gets one door, closed, `door_width_m` wide, in the middle of the longest straight
//   wall it shares with a corridor (else with an area); an area gets one open doorway (up to
//   1.8 m) in the longest wall it shares with a corridor. A room touching neither keeps no door.
// Materials: the feature's material=* tag where it names one of ours, else corridors
// plasterboard, areas concrete, rooms brick (the scene defaults).

#include <algorithm>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.hpp"
#include "floorplan/local_projection.hpp"
#include "floorplan/plan_import.hpp"

namespace wifislam::floorplan {

namespace {

std::optional<sim::scene::SpaceKind> space_kind(const std::string& indoor) {
  if (indoor == "room") return sim::scene::SpaceKind::kRoom;
  if (indoor == "corridor") return sim::scene::SpaceKind::kCorridor;
  if (indoor == "area") return sim::scene::SpaceKind::kArea;
  return std::nullopt;
}

radio_model::WallMaterial material_of(const PlanFeature& f, sim::scene::SpaceKind kind) {
  const std::string m = f.tag("material");
  if (m == "concrete" || m == "reinforced_concrete") return radio_model::WallMaterial::kConcrete;
  if (m == "brick" || m == "stone") return radio_model::WallMaterial::kBrick;
  if (m == "glass") return radio_model::WallMaterial::kGlass;
  if (m == "plaster" || m == "plasterboard" || m == "drywall")
    return radio_model::WallMaterial::kPlasterboard;
  switch (kind) {
    case sim::scene::SpaceKind::kCorridor:
      return radio_model::WallMaterial::kPlasterboard;
    case sim::scene::SpaceKind::kArea:
      return radio_model::WallMaterial::kConcrete;
    case sim::scene::SpaceKind::kRoom:
      return radio_model::WallMaterial::kBrick;
  }
  return radio_model::WallMaterial::kBrick;
}

/// The feature's levels: `level=1`, `level=1;2`.
std::vector<std::string> levels_of(const PlanFeature& f) {
  std::vector<std::string> out;
  std::string level = f.tag("level");
  std::size_t start = 0;
  while (start <= level.size()) {
    const std::size_t end = std::min(level.find(';', start), level.size());
    std::string part = level.substr(start, end - start);
    part.erase(0, part.find_first_not_of(' '));
    part.erase(part.find_last_not_of(' ') + 1);
    if (!part.empty()) out.push_back(part);
    start = end + 1;
  }
  return out;
}

bool on_level(const PlanFeature& f, const std::string& level) {
  const auto levels = levels_of(f);
  return std::find(levels.begin(), levels.end(), level) != levels.end();
}

/// Levels with at least one corridor or area, in numeric order when numbers.
std::vector<std::string> levels_with_spaces(const std::vector<PlanFeature>& features,
                                            std::vector<std::string>& all_levels) {
  std::set<std::string> walkable, all;
  for (const PlanFeature& f : features) {
    const auto kind = space_kind(f.tag("indoor"));
    if (!kind || f.polygons_lon_lat.empty()) continue;
    for (const std::string& l : levels_of(f)) {
      all.insert(l);
      if (*kind != sim::scene::SpaceKind::kRoom) walkable.insert(l);
    }
  }
  auto numeric_order = [](std::vector<std::string> v) {
    std::stable_sort(v.begin(), v.end(), [](const std::string& a, const std::string& b) {
      char* ea = nullptr;
      char* eb = nullptr;
      const double x = std::strtod(a.c_str(), &ea), y = std::strtod(b.c_str(), &eb);
      if (*ea == 0 && *eb == 0 && !a.empty() && !b.empty()) return x < y;
      return a < b;
    });
    return v;
  };
  all_levels = numeric_order({all.begin(), all.end()});
  return numeric_order({walkable.begin(), walkable.end()});
}

/// One door for the input `r` on its longest shared wall with an input of a kind in `with`.
std::optional<PlacedDoor> door_on_longest_wall(int r, const std::vector<SpaceInput>& inputs,
                                               const Partition& partition,
                                               const std::set<sim::scene::SpaceKind>& with,
                                               double max_width_m, bool open) {
  const SharedWall* best = nullptr;
  int other = -1;
  for (const SharedWall& w : partition.shared_walls) {
    const int o = w.a == r ? w.b : w.b == r ? w.a : -1;
    if (o < 0 || !with.count(inputs[o].kind)) continue;
    if (best == nullptr || w.length_m() > best->length_m() + 1e-9) best = &w, other = o;
  }
  if (best == nullptr) return std::nullopt;
  // As wide as asked, but 15 cm of wall left at either jamb; no door narrower than 0.6 m.
  const double width = std::min(max_width_m, best->length_m() - 0.3);
  if (width < 0.6) return std::nullopt;
  const Eigen::Vector2d mid = 0.5 * (best->from_m + best->to_m);
  const Eigen::Vector2d along = (best->to_m - best->from_m).normalized();
  PlacedDoor door;
  door.a = r;
  door.b = other;
  door.door.from_m = mid - 0.5 * width * along;
  door.door.to_m = mid + 0.5 * width * along;
  door.door.open = open;
  return door;
}

}  // namespace

ImportedPlan import_osm_sit(const std::filesystem::path& plan_file,
                            const std::vector<PlanFeature>& features,
                            const ImportOptions& options) {
  ImportedPlan plan;
  plan.format = PlanFormat::kOsmSit;
  plan.source = plan_file.string();
  plan.wall_thickness_m = options.wall_thickness_m;
  const std::vector<std::string> walkable_levels = levels_with_spaces(features, plan.levels);
  if (options.level) {
    if (std::find(plan.levels.begin(), plan.levels.end(), *options.level) == plan.levels.end())
      throw ParseError(plan.source, "--level",
                       fmt::format("no level '{}' in the plan; its levels: {}", *options.level,
                                   fmt::join(plan.levels, ", ")));
    plan.level = *options.level;
  } else if (!walkable_levels.empty()) {
    plan.level = walkable_levels.front();
  } else {
    // A corridor or area feature whose geometry did not read as a polygon (coordinates given as
    // text, a missing ring) is named: "no such polygon" sent users looking for the wrong fault.
    for (const PlanFeature& f : features) {
      const std::string indoor = f.tag("indoor");
      if ((indoor == "corridor" || indoor == "area") && f.polygons_lon_lat.empty()) {
        throw ParseError(f.where, "geometry",
                         fmt::format("indoor={} has no polygon that reads as one (coordinates "
                                     "must be numbers, a ring closed and of 4 points or more)",
                                     indoor));
      }
    }
    throw ParseError(plan.source, "", "no indoor=corridor or indoor=area polygon on any level");
  }

  plan.centre_lon_lat_deg = plan_centre_lon_lat(features);
  const LocalProjection projection(plan.centre_lon_lat_deg.x(), plan.centre_lon_lat_deg.y());
  plan.projection = projection.proj_definition();
  const GeosContext geos;

  std::vector<SpaceInput> inputs;
  std::vector<const PlanFeature*> corridors;
  for (const PlanFeature& f : features) {
    if (!on_level(f, plan.level)) continue;
    const auto kind = space_kind(f.tag("indoor"));
    const bool path_way = !f.lines_lon_lat.empty() &&
                          (f.tag("highway") == "corridor" || f.tag("highway") == "footway");
    if (path_way) {
      add_projected_lines(f, projection, plan.paths_m);
      continue;
    }
    if (!kind || f.polygons_lon_lat.empty()) {
      ++plan.counts.skipped;
      continue;
    }
    (*kind == sim::scene::SpaceKind::kRoom       ? plan.counts.rooms
     : *kind == sim::scene::SpaceKind::kCorridor ? plan.counts.corridors
                                                 : plan.counts.areas)++;
    for (PolygonRings& p : projected_polygons(geos, f, projection)) {
      // Inner rings (a planter in a courtyard) are solid blocks in the space.
      for (Ring& hole : p.holes) plan.obstacles.push_back({std::move(hole)});
      p.holes.clear();
      SpaceInput in;
      const std::string ref = !f.tag("ref").empty() ? f.tag("ref") : f.tag("@id");
      in.id = fmt::format("{}-{}", sim::scene::to_string(*kind), inputs.size());
      in.name = !f.tag("name").empty() ? f.tag("name") : ref;
      in.kind = *kind;
      in.material = material_of(f, *kind);
      in.polygon_m = std::move(p);
      inputs.push_back(std::move(in));
    }
  }
  if (inputs.empty())
    throw ParseError(
        plan.source, "--level",
        fmt::format("level '{}' has no indoor=room|corridor|area polygon", plan.level));

  // Corridors drawn as several touching polygons are one corridor: join them first.
  std::vector<SpaceInput> joined;
  std::vector<Geometry> corridor_parts;
  std::vector<const Geometry*> corridor_ptrs;
  for (const SpaceInput& in : inputs) {
    if (in.kind == sim::scene::SpaceKind::kCorridor) {
      corridor_parts.push_back(geos.polygon(in.polygon_m));
    } else {
      joined.push_back(in);
    }
  }
  for (const Geometry& g : corridor_parts) corridor_ptrs.push_back(&g);
  int corridor_index = 0;
  for (PolygonRings& p : geos.union_all(corridor_ptrs).polygons()) {
    for (Ring& hole : p.holes) plan.obstacles.push_back({std::move(hole)});
    p.holes.clear();
    SpaceInput in;
    in.id = fmt::format("corridor-{}", corridor_index++);
    in.kind = sim::scene::SpaceKind::kCorridor;
    in.material = radio_model::WallMaterial::kPlasterboard;
    in.polygon_m = std::move(p);
    joined.insert(joined.begin() + (corridor_index - 1), std::move(in));
  }
  if (corridor_index > 0 && corridor_parts.size() > static_cast<std::size_t>(corridor_index))
    plan.notes.push_back(fmt::format("{} corridor polygons that touch were joined into {}",
                                     corridor_parts.size(), corridor_index));

  PartitionOptions partition_options;
  partition_options.wall_thickness_m = plan.wall_thickness_m;
  const Partition partition = partition_spaces(geos, joined, partition_options);

  std::vector<PlacedDoor> doors;
  for (std::size_t i = 0; i < joined.size(); ++i) {
    const int r = static_cast<int>(i);
    if (joined[i].kind == sim::scene::SpaceKind::kRoom) {
      auto door = door_on_longest_wall(r, joined, partition, {sim::scene::SpaceKind::kCorridor},
                                       options.door_width_m, false);
      if (!door)
        door = door_on_longest_wall(r, joined, partition, {sim::scene::SpaceKind::kArea},
                                    options.door_width_m, false);
      if (door)
        doors.push_back(*door);
      else
        ++plan.counts.rooms_without_door;
    } else if (joined[i].kind == sim::scene::SpaceKind::kArea) {
      if (auto door = door_on_longest_wall(r, joined, partition, {sim::scene::SpaceKind::kCorridor},
                                           1.8, true))
        doors.push_back(*door);
    }
  }
  plan.notes.push_back(fmt::format(
      "doors inferred (the plan has none): {} rooms got a closed {:.2f} m door on their longest "
      "wall shared with a corridor or area, {} touch neither; areas got an open doorway to a "
      "corridor",
      std::count_if(doors.begin(), doors.end(), [](const PlacedDoor& d) { return !d.door.open; }),
      options.door_width_m, plan.counts.rooms_without_door));
  if (!partition.dropped.empty())
    plan.notes.push_back(fmt::format("{} polygon(s) lay inside others or were slivers; dropped",
                                     partition.dropped.size()));
  finish_plan(geos, joined, partition, partition_options, doors, plan);
  return plan;
}

}  // namespace wifislam::floorplan
