// `wifislam import PLAN -o scene.yaml [--level L] [--format osm-sit|wrld] [--route ...]`: a real
// floor plan (OSM Simple Indoor Tagging, WRLD indoor maps) -> a scene file of one level.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "apps/command_registry.hpp"
#include "apps/option_validators.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "floorplan/imported_scene.hpp"
#include "floorplan/plan_import.hpp"
#include "sim/scene/scene_loader.hpp"

namespace wifislam::cli {

namespace {

struct ImportArgs {
  std::string plan_path, output_path, level, format, route, name, attribution;
  int laps = 2;
  int access_points = 0;
  double wall_thickness_m = 0.15;
  bool all_levels = false;
};

/// "x,y;x,y;..." in the scene's metres.
std::vector<Eigen::Vector2d> parse_route(const std::string& text) {
  std::vector<Eigen::Vector2d> out;
  std::stringstream points(text);
  for (std::string point; std::getline(points, point, ';');) {
    double x = 0, y = 0;
    char comma = 0, extra = 0;
    std::stringstream in(point);
    if (!(in >> x >> comma >> y) || comma != ',' || (in >> extra))
      throw ParseError("--route", "--route",
                       fmt::format("expected x,y;x,y;... in metres, got '{}'", point));
    out.emplace_back(x, y);
  }
  if (out.size() < 2)
    throw ParseError("--route", "--route", "a route needs at least two waypoints");
  return out;
}

/// The attribution file beside the plan, read unless --attribution is given.
std::filesystem::path attribution_file(const ImportArgs& args) {
  return std::filesystem::path(args.plan_path).parent_path() / "ATTRIBUTION.md";
}

/// The attribution beside the plan (ATTRIBUTION.md), unless given: it must travel with the scene.
std::vector<std::string> attribution_lines(const ImportArgs& args) {
  std::vector<std::string> lines;
  std::string text = args.attribution;
  if (text.empty()) {
    std::ifstream in(attribution_file(args));
    std::stringstream all;
    all << in.rdbuf();
    text = all.str();
  }
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  while (!lines.empty() && lines.back().empty()) lines.pop_back();
  return lines;
}

void run_import(const ImportArgs& args) {
  if (!args.name.empty()) {
    if (const std::optional<std::string> problem = sim::scene::scene_name_problem(args.name))
      throw InvalidInputError("--name: " + *problem);
  }
  check_output_file(args.output_path, {args.plan_path});
  floorplan::ImportOptions options;
  if (args.format == "osm-sit") options.format = floorplan::PlanFormat::kOsmSit;
  if (args.format == "wrld") options.format = floorplan::PlanFormat::kWrld;
  if (args.format == "imdf") options.format = floorplan::PlanFormat::kImdf;
  if (!args.level.empty()) options.level = args.level;
  options.wall_thickness_m = args.wall_thickness_m;
  floorplan::ImportedPlan plan = floorplan::import_plan(args.plan_path, options);
  // The files read so far may not be the output either: refused now, not after the scene's
  // route is planned (seconds on a large plan). Other levels' files are checked below.
  std::vector<std::filesystem::path> read_so_far = plan.input_files;
  if (args.attribution.empty()) read_so_far.push_back(attribution_file(args));
  check_output_file(args.output_path, read_so_far);

  floorplan::SceneOptions scene_options;
  scene_options.name = args.name;
  scene_options.laps = args.laps;
  if (args.access_points > 0) scene_options.access_points = args.access_points;
  if (!args.route.empty()) scene_options.route_m = parse_route(args.route);
  std::vector<std::filesystem::path> inputs = plan.input_files;
  sim::scene::Scene scene;
  if (!args.all_levels) {
    scene = floorplan::imported_scene(plan, scene_options);
  } else {
    // Every level the plan has, lowest first, each imported as --level would; the route runs on
    // the level chosen above (--level, else the default level).
    std::vector<floorplan::ImportedPlan> levels;
    for (const std::string& level : plan.levels) {
      floorplan::ImportOptions level_options = options;
      level_options.level = level;
      try {
        levels.push_back(
            level == plan.level ? plan : floorplan::import_plan(args.plan_path, level_options));
      } catch (const ParseError& e) {
        // A level with nothing to build (stairs only, an outline) is left out, and said so.
        plan.notes.push_back(fmt::format("level {} left out: {}", level, e.what()));
        continue;
      }
      inputs.insert(inputs.end(), levels.back().input_files.begin(),
                    levels.back().input_files.end());
    }
    scene = floorplan::imported_building_scene(levels, plan.level, scene_options);
    std::string names;
    for (const auto& l : levels) names += (names.empty() ? "" : ", ") + l.level;
    plan.notes.push_back(fmt::format(
        "levels {} stacked {:g} m apart (wall height {:g} m and a {:g} m concrete slab): the plan "
        "gives no heights",
        names, scene_options.wall_height_m + floorplan::kImportedSlabThicknessM,
        scene_options.wall_height_m, floorplan::kImportedSlabThicknessM));
  }
  const std::string text = floorplan::imported_scene_yaml(plan, scene, attribution_lines(args));
  sim::scene::load_scene_yaml(text, args.output_path);  // what we write, our loader reads
  // Now that the import knows every file it read (main.json, level and paths files beside the
  // plan, an IMDF folder's files, the attribution), none of them may be the output.
  if (args.attribution.empty()) inputs.push_back(attribution_file(args));
  check_output_file(args.output_path, inputs);
  write_file_atomic(args.output_path, text);

  const auto& c = plan.counts;
  fmt::print("level {} of {} ({}; levels: {})\n", plan.level, plan.source,
             floorplan::to_string(plan.format), fmt::join(plan.levels, ", "));
  if (plan.format != floorplan::PlanFormat::kWrld)
    fmt::print("read: {} rooms, {} corridors, {} areas ({} other features skipped{})\n", c.rooms,
               c.corridors, c.areas, c.skipped,
               plan.format == floorplan::PlanFormat::kImdf
                   ? fmt::format("; {} wall units, {} openings", c.walls, c.doors)
                   : std::string());
  else
    fmt::print(
        "read: {} walls, {} doors, {} windows ({} other features skipped); {} spaces "
        "between them\n",
        c.walls, c.doors, c.windows, c.skipped, c.rooms + c.areas);
  fmt::print(
      "scene: {} spaces, {} doors, {} obstacles, walls {:.2f} m; route of {} waypoints "
      "({} laps); {} access points\n",
      c.spaces, c.space_doors, c.obstacles, plan.wall_thickness_m, scene.route.waypoints_m.size(),
      args.laps, scene.access_points.count);
  for (const std::string& note : plan.notes) fmt::print("note: {}\n", note);
  fmt::print("wrote {}\n", args.output_path);
}

}  // namespace

WIFISLAM_COMMAND(import, 15) {
  auto args = std::make_shared<ImportArgs>();
  CLI::App* app = parent.add_subcommand(
      "import",
      "Import one level of a real floor plan into a scene file.\n"
      "Reads OpenStreetMap Simple Indoor Tagging (GeoJSON or .osm XML: indoor=room|corridor|area\n"
      "polygons with level=*), the WRLD indoor map format (a level's GeoJSON, with main.json\n"
      "beside it for --level) or Apple's IMDF (its folder, or unit.geojson), projects lon/lat\n"
      "to metres (transverse Mercator at the plan's centre), gives every wall one thickness,\n"
      "infers doors where the plan has none, and plans a route that loops through the corridors\n"
      "twice. docs/real_buildings/README.md has details.");
  app->add_option("plan", args->plan_path,
                  "Plan file (GeoJSON or .osm; WRLD: a level's GeoJSON; IMDF: its folder)")
      ->required()
      ->check(kNonEmptyInput);
  app->add_option("-o,--output", args->output_path, "Scene file to write (YAML)")->required();
  app->add_option("--level", args->level,
                  "Level to import (OSM level=* value; WRLD level name from main.json; IMDF level "
                  "short name, id or ordinal). Default: the lowest level with corridors (OSM, "
                  "IMDF), the given file (WRLD)");
  app->add_flag("--all-levels", args->all_levels,
                "Import every level of the plan into one building scene (scene key levels:), the "
                "route on --level or the default level");
  app->add_option("--format", args->format, "Plan format (default: from the file's contents)")
      ->check(CLI::IsMember({"osm-sit", "wrld", "imdf"}));
  app->add_option("--route", args->route,
                  "Waypoints x,y;x,y;... in the scene's metres, visited in order (default: a "
                  "planned tour of the corridors, or of the plan's navigation paths)");
  app->add_option("--laps", args->laps, "Times the route goes round its loop")
      ->check(CLI::Range(1, 10));
  app->add_option("--access-points", args->access_points,
                  "Access points (placed in rooms); default one per 100 m^2 of floor, at least 4")
      ->check(CLI::Range(1, 1000));
  app->add_option("--wall-thickness", args->wall_thickness_m,
                  "Wall thickness in metres for OSM and IMDF plans (WRLD measures its own)")
      ->check(finite_range(0.05, 0.5));
  app->add_option("--name", args->name, "Scene name (default: from the file name and level)");
  app->add_option(
      "--attribution", args->attribution,
      "Attribution text for the scene header (default: ATTRIBUTION.md beside the plan)");
  app->callback([args] { run_import(*args); });
}

}  // namespace wifislam::cli
