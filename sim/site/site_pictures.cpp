#include "sim/site/site_pictures.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "radio_model/propagation_model.hpp"
#include "sim/site/radio_map_over_plan.hpp"
#include "sim/site/radio_options.hpp"
#include "sim/world/plan_drawing.hpp"

namespace wifislam::sim::site {

namespace {

/// One level of the site as a picture shows it.
struct LevelView {
  const world::FloorPlan* plan = nullptr;
  double elevation_m = 0.0;
  bool route_level = true;
  std::string id;
};

LevelView level_view(const Site& site, const std::string& level) {
  const world::World& world = site.world();
  if (level.empty() || level == world.level_id)
    return {&world.plan, world.elevation_m, true, world.level_id};
  const world::Storey* storey = world.storey(level);
  if (!storey) {
    std::string ids;
    for (const std::string& id : site_level_ids(site)) ids += (ids.empty() ? "" : ", ") + id;
    throw InvalidInputError(
        ids.empty()
            ? fmt::format("--level {}: the scene has one level (no `levels:` key)", level)
            : fmt::format("--level {}: the scene has no such level (levels: {})", level, ids));
  }
  return {&storey->plan, storey->elevation_m, false, storey->level_id};
}

/// The access points standing on the level: between its floor and its walls' top.
std::vector<radio_model::AccessPoint> access_points_on(const Site& site, const LevelView& view) {
  std::vector<radio_model::AccessPoint> on;
  for (const radio_model::AccessPoint& ap : site.access_points()) {
    const double z_m = ap.position_m.z() - view.elevation_m;
    if (z_m >= 0.0 && z_m <= view.plan->wall_height_m) on.push_back(ap);
  }
  return on;
}

}  // namespace

std::vector<std::string> site_level_ids(const Site& site) {
  std::vector<std::string> ids;
  for (const world::Storey& storey : site.world().storeys) ids.push_back(storey.level_id);
  return ids;
}

void draw_site_plan(const Site& site, const std::filesystem::path& path, const std::string& level) {
  const LevelView view = level_view(site, level);
  world::PlanDrawingOptions options;
  options.title =
      view.id.empty()
          ? fmt::format("{} (seed {})", site.scene().name, site.scene().seed)
          : fmt::format("{}, level {} (seed {})", site.scene().name, view.id, site.scene().seed);
  for (const radio_model::AccessPoint& ap : access_points_on(site, view))
    options.access_points_m.push_back(ap.position_m);
  if (view.route_level) {
    world::draw_floor_plan(site.world(), path, options);
    return;
  }
  world::World level_only;  // the level's plan, without the route (it runs on another level)
  level_only.plan = *view.plan;
  options.draw_route = false;
  world::draw_floor_plan(level_only, path, options);
}

radio_model::RadioMap compute_site_radio_map(const Site& site,
                                             const radio_model::RadioMapOptions& options,
                                             const std::string& level) {
  const LevelView view = level_view(site, level);
  return compute_radio_map(site.radio(), *view.plan, options, view.elevation_m);
}

radio_model::RadioMap draw_site_radio_map(const Site& site,
                                          const radio_model::RadioMapOptions& options,
                                          const std::filesystem::path& path,
                                          const std::string& level) {
  const LevelView view = level_view(site, level);
  const radio_model::RadioMap map = compute_site_radio_map(site, options, level);
  const double floor_dbm = scene::receiver_device(site.scene().sensors.wifi).sensitivity_dbm;
  write_radio_map_png(map, *view.plan, access_points_on(site, view), path, floor_dbm);
  return map;
}

}  // namespace wifislam::sim::site
