#include "sim/site/site_pictures.hpp"

#include <fmt/format.h>

#include "sim/radio/propagation_model.hpp"
#include "sim/radio/wifi_scanner.hpp"
#include "sim/world/plan_drawing.hpp"

namespace wifislam::sim {

void draw_site_plan(const Site& site, const std::filesystem::path& path) {
  PlanDrawingOptions options;
  options.title = fmt::format("{} (seed {})", site.scene().name, site.scene().seed);
  for (const radio::AccessPoint& ap : site.access_points())
    options.access_points_m.push_back(ap.position_m);
  draw_floor_plan(site.world(), path, options);
}

radio::RadioMap draw_site_radio_map(const Site& site, const radio::RadioMapOptions& options,
                                    const std::filesystem::path& path) {
  const radio::RadioMap map = radio::compute_radio_map(site.radio(), site.world().plan, options);
  const double floor_dbm =
      radio::WifiScannerOptions::from_scene(site.scene().sensors.wifi).sensitivity_dbm;
  radio::write_radio_map_png(map, site.world().plan, site.access_points(), path, floor_dbm);
  return map;
}

}  // namespace wifislam::sim
