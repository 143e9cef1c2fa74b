#include "sim/site/radio_options.hpp"

#include <algorithm>

#include "sim/scene/scene_levels.hpp"

namespace wifislam::sim::site {

radio_model::PropagationOptions propagation_options(const scene::Scene& scene) {
  const scene::RadioSpec& radio = scene.radio;
  radio_model::PropagationOptions o;
  o.wall_losses = radio_model::WallLossTable(scene.building.wall_thickness_m);
  o.model = radio.model;
  o.environment = radio.environment;
  o.distance_coefficient = radio.distance_coefficient;
  o.shadowing_sigma_db = radio.shadowing_sigma_db;
  o.shadowing_decorrelation_m = radio.shadowing_decorrelation_m;
  o.fast_fading_sigma_db = radio.fast_fading_sigma_db;
  o.fading_coherence_s = radio.fading_coherence_s;
  o.bssid_spread_db = radio.bssid_spread_db;
  o.people_disturbance_db = radio.people_disturbance_db;
  if (scene::has_levels(scene)) {
    for (const scene::ResolvedLevel& level : scene::resolved_levels(scene))
      o.storey_elevations_m.push_back(level.elevation_m);
    std::sort(o.storey_elevations_m.begin(), o.storey_elevations_m.end());
  }
  for (int m = 0; m < radio_model::kWallMaterialCount; ++m) {
    if (const auto& loss_db = radio.wall_loss_db.by_material_db[m])
      o.wall_losses.laws[m] = radio_model::WallLossLaw::linear(*loss_db, 0.0);  // flat in frequency
  }
  return o;
}

radio_model::WifiScannerOptions wifi_scanner_options(const scene::WifiScannerSpec& spec) {
  radio_model::WifiScannerOptions o;
  o.device = scene::receiver_device(spec);
  return o;
}

}  // namespace wifislam::sim::site
