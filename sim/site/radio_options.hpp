#pragma once
// The radio model's options from a scene, built here and nowhere else: the scene's `radio` block
// and its building's wall thickness become radio_model::PropagationOptions, its
// `sensors.wifi` block radio_model::WifiScannerOptions. Keys the scene does not set keep the
// radio model's defaults.

#include "radio_model/propagation_model.hpp"
#include "radio_model/wifi_scanner.hpp"
#include "sim/scene/scene.hpp"

namespace wifislam::sim::site {

/// The scene's radio keys, and wall losses for its building's wall thickness (a measured
/// `radio.wall_loss_db` replaces that material's law by a loss flat in frequency).
radio_model::PropagationOptions propagation_options(const scene::Scene& scene);

radio_model::WifiScannerOptions wifi_scanner_options(const scene::WifiScannerSpec& spec);

}  // namespace wifislam::sim::site
