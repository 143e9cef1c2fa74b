#pragma once
// The features of a vector floor-plan file (GeoJSON, or OSM XML), read through GDAL/OGR: their
// tags and their polygons and lines in longitude/latitude. Format-specific meaning (which
// features are rooms, walls, doors, on which level) is the importers' business.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "floorplan/geos_geometry.hpp"

namespace wifislam::floorplan {

struct PlanFeature {
  /// For messages: "file: feature 12 (way/1002786274)".
  std::string where;
  std::map<std::string, std::string> tags;
  /// Polygons (outer ring, then holes), in lon/lat degrees; a multipolygon gives several.
  std::vector<PolygonRings> polygons_lon_lat;
  /// Lines, in lon/lat degrees.
  std::vector<Ring> lines_lon_lat;

  std::string tag(const std::string& key) const {
    auto it = tags.find(key);
    return it == tags.end() ? std::string() : it->second;
  }
};

/// Every feature of every layer of `file`. Throws IoError when the file does not exist and
/// ParseError naming the file when GDAL cannot open it as vector data.
std::vector<PlanFeature> read_plan_features(const std::filesystem::path& file);

}  // namespace wifislam::floorplan
