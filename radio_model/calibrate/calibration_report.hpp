#pragma once
// What `radio calibrate` writes: the fitted constants as scene blocks (`radio:` and an explicit
// `access_points:` list carrying each AP's fitted tx power), and a report of the fit (markdown
// for people, JSON for scripts) with residuals per AP before (the scene as it is) and after,
// on the fitted survey and on a held-out one, next to a plain log-distance fit.

#include <optional>
#include <string>

#include "radio_model/calibrate/propagation_fit.hpp"
#include "radio_model/calibrate/shadowing_statistics.hpp"
#include "radio_model/calibrate/survey_links.hpp"

namespace wifislam::radio_model::calibrate {

struct Calibration {
  std::string scene_name, scene_path, survey_path, test_path;
  double frequency_mhz = 2437.0;
  SurveyLinks train;
  std::optional<SurveyLinks> test;
  LinearRadioModel before;    // the scene's model
  PropagationFit fit;         // after
  LinearRadioModel baseline;  // plain log-distance, one intercept
  ShadowingStatistics shadowing;
  std::optional<HeldOutDeviceScore> held_out;  // --held-out-device
};

/// The `radio:` and `access_points:` blocks (YAML). Values are clamped to the scene schema's
/// ranges, with a comment where a value was.
std::string calibration_scene_yaml(const Calibration& c);
std::string calibration_report_markdown(const Calibration& c);
std::string calibration_report_json(const Calibration& c);

}  // namespace wifislam::radio_model::calibrate
