#include "sim/site/site_pictures.hpp"

#include <fmt/format.h>

#include "radio_model/propagation_model.hpp"
#include "sim/site/radio_map_over_plan.hpp"
#include "sim/site/radio_options.hpp"
#include "sim/world/plan_drawing.hpp"

namespace wifislam::sim {

void draw_site_plan(const Site& site, const std::filesystem::path& path) {
  PlanDrawingOptions options;
  options.title = fmt::format("{} (seed {})", site.scene().name, site.scene().seed);
  for (const radio_model::AccessPoint& ap : site.access_points())
    options.access_points_m.push_back(ap.position_m);
  draw_floor_plan(site.world(), path, options);
}

radio_model::RadioMap draw_site_radio_map(const Site& site,
                                          const radio_model::RadioMapOptions& options,
                                          const std::filesystem::path& path) {
  const radio_model::RadioMap map = compute_radio_map(site.radio(), site.world().plan, options);
  const double floor_dbm = wifi_scanner_options(site.scene().sensors.wifi).sensitivity_dbm;
  write_radio_map_png(map, site.world().plan, site.access_points(), path, floor_dbm);
  return map;
}

}  // namespace wifislam::sim
