// Apple's Indoor Mapping Data Format (IMDF, OGC Community Standard 20-094): a folder of GeoJSON
// files; here level.geojson (id, ordinal, name/short_name labels), unit.geojson (polygons with a
// category and a level_id) and opening.geojson (lines with a level_id). It has OSM's shape:
// units are spaces that touch, openings are doors on their shared walls.
//   walkway -> corridor; lobby, unenclosedarea, platform, footbridge -> area; wall and structure
//   units (brick, concrete, drywall, glass, wood, column, structure) and voids (opentobelow,
//   elevator, stairs, escalator, steps, ramp, vegetation, road) are not free space; every other
//   unit is a room. Every opening is an open door on the shared wall it lies on (door_placement).
// Materials: rooms brick, corridors plasterboard, areas concrete (the scene defaults).

#include <algorithm>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "floorplan/door_placement.hpp"
#include "floorplan/local_projection.hpp"
#include "floorplan/plan_import.hpp"

namespace wifislam::floorplan {

namespace {

/// An IMDF label ({"en": "Level 1"}) as GDAL hands it over (JSON text), or plain text: its first
/// language's value.
std::string label(const std::string& text) {
  if (text.empty() || text.front() != '{') return text;
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (!j.is_object() || j.empty() || !j.begin()->is_string()) return text;
  return j.begin()->get<std::string>();
}

enum class UnitUse { kSpace, kSolid, kVoid };

UnitUse unit_use(const std::string& category, sim::scene::SpaceKind& kind) {
  static const std::set<std::string> solid = {"brick", "concrete", "drywall",  "glass",
                                              "wood",  "column",   "structure"};
  static const std::set<std::string> voids = {"opentobelow", "elevator", "stairs",
                                              "escalator",   "steps",    "ramp",
                                              "vegetation",  "road",     "movingwalkway"};
  static const std::set<std::string> areas = {"lobby", "unenclosedarea", "platform", "footbridge"};
  if (solid.count(category)) return UnitUse::kSolid;
  if (voids.count(category)) return UnitUse::kVoid;
  kind = category == "walkway" || category == "walkway.island" ? sim::scene::SpaceKind::kCorridor
         : areas.count(category)                               ? sim::scene::SpaceKind::kArea
                                                               : sim::scene::SpaceKind::kRoom;
  return UnitUse::kSpace;
}

radio_model::WallMaterial default_material(sim::scene::SpaceKind kind) {
  return kind == sim::scene::SpaceKind::kCorridor ? radio_model::WallMaterial::kPlasterboard
         : kind == sim::scene::SpaceKind::kArea   ? radio_model::WallMaterial::kConcrete
                                                  : radio_model::WallMaterial::kBrick;
}

struct Level {
  std::string id, name;
  double ordinal = 0;
};

std::vector<Level> read_levels(const std::filesystem::path& folder, ImportedPlan& plan) {
  std::vector<Level> levels;
  const std::filesystem::path file = folder / "level.geojson";
  if (!std::filesystem::exists(file)) return levels;
  plan.input_files.push_back(file);
  for (const PlanFeature& f : read_plan_features(file)) {
    Level l;
    l.id = f.tag("id");
    l.name = label(f.tag("short_name"));
    if (l.name.empty()) l.name = label(f.tag("name"));
    if (l.name.empty()) l.name = l.id;
    l.ordinal = std::atof(f.tag("ordinal").c_str());
    levels.push_back(std::move(l));
  }
  std::stable_sort(levels.begin(), levels.end(),
                   [](const Level& a, const Level& b) { return a.ordinal < b.ordinal; });
  return levels;
}

std::vector<std::string> level_ids(const std::vector<Level>& levels) {
  std::vector<std::string> ids;
  for (const Level& l : levels) ids.push_back(l.id);
  return ids;
}

}  // namespace

ImportedPlan import_imdf(const std::filesystem::path& plan_file,
                         const std::vector<PlanFeature>& given_units,
                         const ImportOptions& options) {
  ImportedPlan plan;
  plan.format = PlanFormat::kImdf;
  plan.source = plan_file.string();
  plan.wall_thickness_m = options.wall_thickness_m;
  const std::filesystem::path folder = plan_file.parent_path();
  const std::vector<Level> levels = read_levels(folder, plan);
  for (const Level& l : levels) plan.levels.push_back(l.name);

  // The level: asked for by name, id or ordinal; else the lowest with a walkway.
  std::string level_id;
  if (options.level) {
    for (const Level& l : levels)
      if (l.name == *options.level || l.id == *options.level ||
          fmt::format("{}", l.ordinal) == *options.level)
        level_id = l.id, plan.level = l.name;
    if (level_id.empty())
      throw ParseError(
          plan.source, "--level",
          fmt::format("no level '{}'; its levels: {}", *options.level,
                      levels.empty() ? std::string("(no level.geojson beside it)")
                                     : fmt::format("{}", fmt::join(plan.levels, ", "))));
  } else {
    for (const Level& l : levels) {
      const bool walkable = std::any_of(given_units.begin(), given_units.end(), [&](const auto& u) {
        sim::scene::SpaceKind kind;
        return u.tag("level_id") == l.id && unit_use(u.tag("category"), kind) == UnitUse::kSpace &&
               kind != sim::scene::SpaceKind::kRoom;
      });
      if (walkable) {
        level_id = l.id, plan.level = l.name;
        break;
      }
    }
    if (level_id.empty()) {
      // Say which input is at fault: no level file, or units on a level it does not list.
      if (levels.empty()) {
        throw IoError((folder / "level.geojson").string() +
                      ": not found; an IMDF venue lists its levels there, and each unit names "
                      "its level by level_id");
      }
      for (const PlanFeature& u : given_units) {
        const std::string id = u.tag("level_id");
        if (std::none_of(levels.begin(), levels.end(), [&](const Level& l) { return l.id == id; }))
          throw ParseError(u.where, "level_id",
                           fmt::format("'{}' is not a level of level.geojson (its level ids: {})",
                                       id, fmt::join(level_ids(levels), ", ")));
      }
      throw ParseError(plan.source, "", "no level with a walkway or lobby unit");
    }
  }

  std::vector<PlanFeature> units;
  for (const PlanFeature& u : given_units)
    if (u.tag("level_id") == level_id) units.push_back(u);
  plan.centre_lon_lat_deg = plan_centre_lon_lat(units);
  const LocalProjection projection(plan.centre_lon_lat_deg.x(), plan.centre_lon_lat_deg.y());
  plan.projection = projection.proj_definition();
  const GeosContext geos;

  std::vector<SpaceInput> inputs;
  for (const PlanFeature& u : units) {
    sim::scene::SpaceKind kind = sim::scene::SpaceKind::kRoom;
    const UnitUse use = unit_use(u.tag("category"), kind);
    std::vector<PolygonRings> polygons = projected_polygons(geos, u, projection);
    if (use == UnitUse::kSolid) ++plan.counts.walls;
    if (use != UnitUse::kSpace || polygons.empty()) {
      plan.counts.skipped += use == UnitUse::kVoid;
      continue;
    }
    (kind == sim::scene::SpaceKind::kRoom       ? plan.counts.rooms
     : kind == sim::scene::SpaceKind::kCorridor ? plan.counts.corridors
                                                : plan.counts.areas)++;
    for (PolygonRings& p : polygons) {
      for (Ring& hole : p.holes) plan.obstacles.push_back({std::move(hole)});
      p.holes.clear();
      SpaceInput in;
      in.id = fmt::format("{}-{}", sim::scene::to_string(kind), inputs.size());
      in.name = label(u.tag("name"));
      in.kind = kind;
      in.material = default_material(kind);
      in.polygon_m = std::move(p);
      inputs.push_back(std::move(in));
    }
  }
  if (inputs.empty())
    throw ParseError(plan.source, "--level",
                     fmt::format("level '{}' has no unit that is free space", plan.level));
  PartitionOptions partition_options;
  partition_options.wall_thickness_m = plan.wall_thickness_m;
  const Partition partition = partition_spaces(geos, inputs, partition_options);

  std::vector<PlacedDoor> doors;
  const std::filesystem::path openings = folder / "opening.geojson";
  if (std::filesystem::exists(openings)) {
    plan.input_files.push_back(openings);
    for (const PlanFeature& o : read_plan_features(openings)) {
      if (o.tag("level_id") != level_id) continue;
      for (const Ring& line : o.lines_lon_lat) {
        if (line.size() < 2) continue;
        ++plan.counts.doors;
        Ring m;
        for (const auto& p : line) m.push_back(projection.to_local_m(p));
        if (auto door = door_on_shared_wall(opening_shape(m), partition, true))
          doors.push_back(*door);
        else
          ++plan.counts.doors_not_placed;
      }
    }
  }
  plan.notes.push_back(fmt::format("{} of {} openings placed as open doors on a shared wall",
                                   doors.size(), plan.counts.doors));
  finish_plan(geos, inputs, partition, partition_options, doors, plan);
  return plan;
}

}  // namespace wifislam::floorplan
