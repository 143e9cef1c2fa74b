// The WRLD indoor map format (github.com/wrld3d/wrld-indoor-maps-api, FORMAT.md): a main.json
// listing the levels, one GeoJSON per level whose features have a `type`: building_outline,
// wall, window, door (all polygons with their real thickness), room, stairs, ... and optional
// `<level>-paths.geojson` navigation paths. Rooms are mostly implicit (the space between walls).
//
// Here: free space = the level's outline minus walls, windows and doors; each piece of it is a
// space (an area if at least 4 m^2, else a room: closets and shafts). Space partition gives every
// wall one thickness, the median of the file's walls (2 x area / perimeter of each wall polygon).
// Each door polygon becomes an open door on the shared wall nearest its centre and parallel to
// its long axis (the plan's paths go through doors). Windows are wall here: the scene's walls
// take their space's material, so a glass pane is not told apart (noted in the docs).

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "floorplan/door_placement.hpp"
#include "floorplan/local_projection.hpp"
#include "floorplan/plan_import.hpp"

namespace wifislam::floorplan {

namespace {

struct LevelFile {
  std::string name;
  std::filesystem::path file;
};

struct MainJson {
  std::vector<LevelFile> levels;                // in z order
  std::optional<Eigen::Vector2d> location_deg;  // the building's point, lon/lat
};

/// The levels of main.json, in z order, and the building's location.
MainJson read_main_json(const std::filesystem::path& main_json) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(main_json, ec))
    throw ParseError(main_json.string(), "", "is not a regular file; expected WRLD's main.json");
  std::ifstream in(main_json);
  if (!in) throw IoError(main_json.string() + ": cannot read");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw ParseError(main_json.string(), "", std::string("not JSON: ") + e.what());
  }
  if (!j.is_object() || !j.contains("levels") || !j["levels"].is_array())
    throw ParseError(main_json.string(), "levels", "a WRLD main.json lists its levels");
  std::vector<std::pair<double, LevelFile>> levels;
  for (std::size_t i = 0; i < j["levels"].size(); ++i) {
    const auto& l = j["levels"][i];
    const std::string key = fmt::format("levels[{}]", i);
    if (!l.is_object() || !l.contains("filename") || !l.contains("name"))
      throw ParseError(main_json.string(), key, "each level needs name and filename");
    if (!l["name"].is_string() || !l["filename"].is_string())
      throw ParseError(main_json.string(), key, "name and filename must be strings");
    if (l.contains("z_order") && !l["z_order"].is_number())
      throw ParseError(main_json.string(), key + ".z_order", "must be a number");
    levels.push_back({l.value("z_order", 0.0),
                      {l["name"].get<std::string>(),
                       main_json.parent_path() / l["filename"].get<std::string>()}});
  }
  std::stable_sort(levels.begin(), levels.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  MainJson out;
  for (auto& [z, l] : levels) out.levels.push_back(std::move(l));
  // The building's point (GeoJSON: {"type": "Point", "coordinates": [lon, lat]}) places the plan;
  // without one the plan's centre does. One that is there but malformed is an error, not a
  // silent fall-back to another origin.
  if (j.contains("location")) {
    const auto& location = j["location"];
    const auto fail = [&](const char* why) {
      throw ParseError(main_json.string(), "location.coordinates", why);
    };
    if (!location.is_object() || !location.contains("coordinates")) {
      fail("expected the building's point, {\"type\": \"Point\", \"coordinates\": [lon, lat]}");
    }
    const auto& lon_lat = location["coordinates"];
    if (!lon_lat.is_array() || lon_lat.size() != 2 || !lon_lat[0].is_number() ||
        !lon_lat[1].is_number()) {
      fail("expected [longitude, latitude] in degrees, two numbers");
    }
    const Eigen::Vector2d deg(lon_lat[0].get<double>(), lon_lat[1].get<double>());
    if (!(std::abs(deg.x()) <= 180.0 && std::abs(deg.y()) <= 90.0)) {
      fail("expected a longitude from -180 to 180 and a latitude from -90 to 90 degrees");
    }
    out.location_deg = deg;
  }
  return out;
}

double median_wall_thickness_m(const GeosContext& geos, const std::vector<PolygonRings>& walls) {
  std::vector<double> t;
  for (const PolygonRings& w : walls) {
    const Geometry g = geos.polygon(w);
    const double perimeter = g.boundary().length_m();
    if (perimeter > 0) t.push_back(2 * g.area_m2() / perimeter);
  }
  if (t.empty()) return 0.15;
  std::nth_element(t.begin(), t.begin() + t.size() / 2, t.end());
  return std::clamp(std::round(t[t.size() / 2] * 100) / 100, 0.08, 0.4);
}

}  // namespace

ImportedPlan import_wrld(const std::filesystem::path& plan_file,
                         const std::vector<PlanFeature>& given_features,
                         const ImportOptions& options) {
  ImportedPlan plan;
  plan.format = PlanFormat::kWrld;
  plan.source = plan_file.string();
  // The level file: the one given, or (main.json beside it) the level asked for.
  std::filesystem::path level_file = plan_file;
  std::vector<PlanFeature> features = given_features;
  const std::filesystem::path main_json = plan_file.parent_path() / "main.json";
  MainJson building;
  if (std::filesystem::exists(main_json)) {
    building = read_main_json(main_json);
    plan.input_files.push_back(main_json);
  }
  const std::vector<LevelFile>& levels = building.levels;
  for (const LevelFile& l : levels) plan.levels.push_back(l.name);
  const auto this_level = std::find_if(levels.begin(), levels.end(), [&](const LevelFile& l) {
    std::error_code ec;  // a level file main.json names but the folder lacks is no match
    return std::filesystem::equivalent(l.file, plan_file, ec);
  });
  // A file beside main.json that is none of its levels (the building's outline file, say) is
  // no level to import: it would give one empty hall.
  if (!levels.empty() && this_level == levels.end() && !options.level) {
    throw ParseError(plan.source, "",
                     fmt::format("not one of the levels main.json beside it lists ({}); give a "
                                 "level's file, or --level NAME",
                                 fmt::join(plan.levels, ", ")));
  }
  plan.level = this_level != levels.end() ? this_level->name : plan_file.stem().string();
  if (options.level && *options.level != plan.level) {
    const auto wanted = std::find_if(levels.begin(), levels.end(),
                                     [&](const LevelFile& l) { return l.name == *options.level; });
    if (wanted == levels.end())
      throw ParseError(plan.source, "--level",
                       fmt::format("no level '{}' {}", *options.level,
                                   levels.empty() ? std::string("(no main.json beside the plan)")
                                                  : fmt::format("in main.json; its levels: {}",
                                                                fmt::join(plan.levels, ", "))));
    level_file = wanted->file;
    features = read_plan_features(level_file);
    plan.input_files.push_back(level_file);
    plan.level = wanted->name;
  }

  // Every level of a building in one frame: centred on main.json's location when it has one.
  plan.centre_lon_lat_deg = building.location_deg.value_or(plan_centre_lon_lat(features));
  const LocalProjection projection(plan.centre_lon_lat_deg.x(), plan.centre_lon_lat_deg.y());
  plan.projection = projection.proj_definition();
  const GeosContext geos;

  std::vector<PolygonRings> outlines, walls, solids, doors;
  for (const PlanFeature& f : features) {
    const std::string type = f.tag("type");
    if (type != "building_outline" && type != "wall" && type != "window" && type != "door") {
      ++plan.counts.skipped;
      continue;
    }
    std::vector<PolygonRings> polygons = projected_polygons(geos, f, projection);
    if (type == "building_outline")
      outlines.insert(outlines.end(), polygons.begin(), polygons.end());
    if (type == "wall")
      ++plan.counts.walls, walls.insert(walls.end(), polygons.begin(), polygons.end());
    if (type == "window") ++plan.counts.windows;
    if (type == "door")
      ++plan.counts.doors, doors.insert(doors.end(), polygons.begin(), polygons.end());
    if (type != "building_outline") solids.insert(solids.end(), polygons.begin(), polygons.end());
  }
  if (outlines.empty())
    throw ParseError(level_file.string(), "", "no building_outline polygon on this level");
  plan.wall_thickness_m = median_wall_thickness_m(geos, walls);

  std::vector<Geometry> parts;
  std::vector<const Geometry*> outline_ptrs, solid_ptrs;
  for (const PolygonRings& p : outlines) parts.push_back(geos.polygon(p));
  for (const Geometry& g : parts) outline_ptrs.push_back(&g);
  std::vector<Geometry> solid_parts;
  for (const PolygonRings& p : solids) solid_parts.push_back(geos.polygon(p));
  for (const Geometry& g : solid_parts) solid_ptrs.push_back(&g);
  const Geometry free = geos.union_all(outline_ptrs).minus(geos.union_all(solid_ptrs));

  std::vector<SpaceInput> inputs;
  for (PolygonRings& p : free.polygons()) {
    // Pillars and wall islands inside a space stay solid blocks.
    for (Ring& hole : p.holes) plan.obstacles.push_back({std::move(hole)});
    p.holes.clear();
    SpaceInput in;
    const double area = geos.polygon(p).area_m2();
    if (area < 0.5) continue;
    in.kind = area >= 4.0 ? sim::scene::SpaceKind::kArea : sim::scene::SpaceKind::kRoom;
    in.id = fmt::format("space-{}", inputs.size());
    in.material = radio_model::WallMaterial::kBrick;
    in.polygon_m = std::move(p);
    inputs.push_back(std::move(in));
  }
  PartitionOptions partition_options;
  partition_options.wall_thickness_m = plan.wall_thickness_m;
  const Partition partition = partition_spaces(geos, inputs, partition_options);
  std::vector<PlacedDoor> placed;
  for (const PolygonRings& d : doors) {
    if (auto door = door_on_shared_wall(door_shape(d.outer), partition, true))
      placed.push_back(*door);
    else
      ++plan.counts.doors_not_placed;
  }
  plan.counts.areas =
      static_cast<int>(std::count_if(inputs.begin(), inputs.end(), [](const auto& i) {
        return i.kind == sim::scene::SpaceKind::kArea;
      }));
  plan.counts.rooms = static_cast<int>(inputs.size()) - plan.counts.areas;
  plan.notes.push_back(fmt::format(
      "walls {:.2f} m thick (the median of the level's {} wall polygons); {} of {} door polygons "
      "placed as open doors on a shared wall",
      plan.wall_thickness_m, plan.counts.walls, placed.size(), plan.counts.doors));

  // Navigation paths of this level, if the plan has them.
  const std::filesystem::path paths_file =
      level_file.parent_path() / (level_file.stem().string() + "-paths.geojson");
  if (std::filesystem::exists(paths_file)) {
    plan.input_files.push_back(paths_file);
    for (const PlanFeature& f : read_plan_features(paths_file))
      add_projected_lines(f, projection, plan.paths_m);
  }
  finish_plan(geos, inputs, partition, partition_options, placed, plan);
  return plan;
}

}  // namespace wifislam::floorplan
