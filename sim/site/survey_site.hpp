#pragma once
// A site as `radio calibrate` needs it (radio_model/calibrate/survey_links.hpp): the world's walls,
// its plan's bounds and free space, the building's ceiling, and the scene's radio options and seed.

#include "radio_model/calibrate/survey_links.hpp"
#include "sim/site/site.hpp"

namespace wifislam::sim::site {

/// Holds a reference to `site`'s world: `site` must outlive the result.
radio_model::calibrate::SurveySite survey_site(const Site& site);

}  // namespace wifislam::sim::site
