#pragma once
// The pictures of a site, made one way for every command that shows them (world, radiomap,
// demo): the floor plan with the site's access points, and the radio map with the cells below
// the scanner's sensitivity left grey (the floor of what a dataset's scans can hear).

#include <filesystem>

#include "radio_model/radio_map.hpp"
#include "sim/site/site.hpp"

namespace wifislam::sim {

/// The plan (walls, doors, lights, route, access points), titled "<scene> (seed N)"; PNG, or SVG
/// when `path` ends in ".svg".
void draw_site_plan(const Site& site, const std::filesystem::path& path);

/// Computes the site's radio map with `options` and draws it as a PNG at `path`; returns the map.
radio_model::RadioMap draw_site_radio_map(const Site& site,
                                          const radio_model::RadioMapOptions& options,
                                          const std::filesystem::path& path);

}  // namespace wifislam::sim
