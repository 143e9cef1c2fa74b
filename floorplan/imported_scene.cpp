#include "floorplan/imported_scene.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "core/error.hpp"
#include "floorplan/route_planner.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/world/floor_plan_builder.hpp"
#include "sim/world/plan_queries.hpp"
#include "sim/world/route_builder.hpp"

namespace wifislam::floorplan {

namespace {

std::string default_name(const ImportedPlan& plan) {
  std::string stem = std::filesystem::path(plan.source).stem().string();
  std::string name;
  for (char c : stem + "_level_" + plan.level)
    name += std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::tolower(c)) : '_';
  // A scene name starts with a letter or digit and has at most 100 characters
  // (sim/scene/scene_loader.hpp, scene_name_problem).
  name.erase(0, name.find_first_not_of('_'));
  if (name.empty()) name = "plan";
  return name.substr(0, 100);
}

}  // namespace

sim::scene::Scene imported_scene(const ImportedPlan& plan, const SceneOptions& options) {
  sim::scene::Scene scene;
  scene.name = options.name.empty() ? default_name(plan) : options.name;
  scene.description =
      fmt::format("Level {} of {} ({} plan), imported by wifislam import.", plan.level,
                  std::filesystem::path(plan.source).filename().string(), to_string(plan.format));
  scene.seed = options.seed;
  scene.building.wall_height_m = options.wall_height_m;
  scene.building.wall_thickness_m = plan.wall_thickness_m;
  scene.spaces = plan.spaces;
  scene.doors = plan.doors;
  scene.obstacles = plan.obstacles;
  // Corners rounded tighter than in our corridor scenes: real corridors meet doors and jogs.
  scene.route.turn_radius_m = 0.3;
  scene.route.min_wall_clearance_m = 0.3;

  const sim::world::FloorPlan floor_plan = sim::world::build_floor_plan(scene);
  const double free_m2 = sim::world::regions_area_m2(floor_plan.free_space);
  scene.access_points.placement = sim::scene::ApPlacement::kRooms;
  scene.access_points.count =
      options.access_points.value_or(std::max(4, static_cast<int>(std::lround(free_m2 / 100.0))));

  TourOptions tour;
  tour.laps = options.laps;
  std::vector<Eigen::Vector2d> visit = options.route_m;
  const bool keep_order = !visit.empty();
  if (!keep_order)
    for (const Ring& path : plan.paths_m) visit.insert(visit.end(), path.begin(), path.end());
  scene.route.waypoints_m = plan_tour(floor_plan, visit, tour, keep_order);
  sim::world::build_route(scene, floor_plan);  // the same check generate makes
  return scene;
}

sim::scene::Scene imported_building_scene(const std::vector<ImportedPlan>& levels,
                                          const std::string& route_level,
                                          const SceneOptions& options) {
  const auto route_plan = std::find_if(
      levels.begin(), levels.end(), [&](const ImportedPlan& p) { return p.level == route_level; });
  if (route_plan == levels.end())
    throw InvalidInputError("import: the route's level '" + route_level + "' was not imported");
  // The route level's scene as a one-level import makes it: route, access point count, defaults.
  sim::scene::Scene scene = imported_scene(*route_plan, options);
  scene.name = options.name.empty() ? default_name(*route_plan) + "_building" : options.name;
  std::string names;
  for (const ImportedPlan& p : levels) names += (names.empty() ? "" : ", ") + p.level;
  scene.description =
      fmt::format("Levels {} of {} ({} plan), imported by wifislam import; the route on level {}.",
                  names, std::filesystem::path(route_plan->source).filename().string(),
                  to_string(route_plan->format), route_level);
  scene.spaces.clear();
  scene.doors.clear();
  scene.obstacles.clear();
  // Rounded to the micrometre, so the scene says 3.1 m, not 3.0999999999999996.
  const auto micrometres = [](double m) { return std::round(m * 1e6) / 1e6; };
  const double storey_m = micrometres(options.wall_height_m + kImportedSlabThicknessM);
  for (std::size_t k = 0; k < levels.size(); ++k) {
    const ImportedPlan& plan = levels[k];
    sim::scene::Level level;
    level.id = plan.level;
    level.elevation_m = micrometres(static_cast<double>(k) * storey_m);
    level.storey_height_m = storey_m;
    level.slab_thickness_m = kImportedSlabThicknessM;
    level.slab_material = radio_model::WallMaterial::kConcrete;
    scene.levels.push_back(level);
    for (sim::scene::Space space : plan.spaces) {
      space.id = plan.level + "/" + space.id;
      space.level = plan.level;
      scene.spaces.push_back(std::move(space));
    }
    for (sim::scene::SpaceDoor door : plan.doors) {
      door.level = plan.level;
      scene.doors.push_back(door);
    }
    for (sim::scene::Obstacle obstacle : plan.obstacles) {
      obstacle.level = plan.level;
      scene.obstacles.push_back(std::move(obstacle));
    }
  }
  scene.route.level = route_level;
  return scene;
}

std::string imported_scene_yaml(const ImportedPlan& plan, const sim::scene::Scene& scene,
                                const std::vector<std::string>& attribution_lines) {
  std::ostringstream out;
  out << fmt::format("# {}: level {} of {}\n", scene.name, plan.level, plan.source);
  out << fmt::format(
      "# Imported by `wifislam import` ({} format; docs/real_buildings/README.md says "
      "what is inferred).\n",
      to_string(plan.format));
  out << fmt::format(
      "# Local frame: {} (lon {:.7f}, lat {:.7f} is the origin; x east, y north, "
      "metres).\n",
      plan.projection, plan.centre_lon_lat_deg.x(), plan.centre_lon_lat_deg.y());
  for (const std::string& note : plan.notes) out << "# Note: " << note << ".\n";
  if (!attribution_lines.empty()) {
    out << "#\n# Source data attribution (keep it with this file and anything derived from it):\n";
    for (const std::string& line : attribution_lines) out << "#   " << line << "\n";
  }
  out << sim::scene::resolved_scene_yaml(scene);
  return out.str();
}

}  // namespace wifislam::floorplan
