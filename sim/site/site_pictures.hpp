#pragma once
// The pictures of a site, made one way for every command that shows them (world, radiomap,
// demo): the floor plan with the site's access points, and the radio map with the cells below
// the scanner's sensitivity left grey (the floor of what a dataset's scans can hear).
//
// A building of several levels draws one level per picture: `level` names it (empty: the
// route's level). The access points drawn are that level's; a radio map of a level hears every
// level's, through the slabs.

#include <filesystem>
#include <string>
#include <vector>

#include "radio_model/radio_map.hpp"
#include "sim/site/site.hpp"

namespace wifislam::sim::site {

/// The ids of the site's levels, lowest first (empty for a one-level scene).
std::vector<std::string> site_level_ids(const Site& site);

/// The plan (walls, doors, lights, route, access points), titled "<scene> (seed N)"; PNG, or SVG
/// when `path` ends in ".svg". Throws InvalidInputError for a level the scene does not have.
void draw_site_plan(const Site& site, const std::filesystem::path& path,
                    const std::string& level = "");

/// The site's radio map on `level` (empty: the route's) with `options`, the receiver height above
/// that level's floor. Throws InvalidInputError for a level the scene does not have.
radio_model::RadioMap compute_site_radio_map(const Site& site,
                                             const radio_model::RadioMapOptions& options,
                                             const std::string& level = "");

/// Computes the site's radio map on `level` with `options` (receiver height above that level's
/// floor) and draws it as a PNG at `path`; returns the map.
radio_model::RadioMap draw_site_radio_map(const Site& site,
                                          const radio_model::RadioMapOptions& options,
                                          const std::filesystem::path& path,
                                          const std::string& level = "");

}  // namespace wifislam::sim::site
