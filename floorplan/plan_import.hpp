#pragma once
// `wifislam import`: a real floor plan (OSM Simple Indoor Tagging GeoJSON/XML, the WRLD indoor
// map format, or Apple's IMDF) -> one level in scene terms (imported_plan.hpp).
// docs/real_buildings/README.md states every inference (doors, wall thickness, materials, walkable
// spaces).

#include <filesystem>

#include "floorplan/imported_plan.hpp"
#include "floorplan/plan_features.hpp"

namespace wifislam::floorplan {

/// Reads and converts one level. Errors are located at the file, feature or option: ParseError
/// for an unreadable file, a self-intersecting ring, a level that does not exist or a plan with
/// no usable polygon; IoError when the file is missing.
ImportedPlan import_plan(const std::filesystem::path& plan_file, const ImportOptions& options);

// The two formats (osm_sit_import.cpp, wrld_import.cpp), given the file's features.
ImportedPlan import_osm_sit(const std::filesystem::path& plan_file,
                            const std::vector<PlanFeature>& features, const ImportOptions& options);
ImportedPlan import_wrld(const std::filesystem::path& level_file,
                         const std::vector<PlanFeature>& features, const ImportOptions& options);
ImportedPlan import_imdf(const std::filesystem::path& unit_file,
                         const std::vector<PlanFeature>& units, const ImportOptions& options);

/// Each ring of the feature's polygons projected to metres, checked to be a valid polygon
/// (ParseError at the feature naming GEOS's reason otherwise).
std::vector<PolygonRings> projected_polygons(const GeosContext& geos, const PlanFeature& feature,
                                             const class LocalProjection& projection);

/// The feature's lines projected to metres, appended to `out` (navigation paths).
void add_projected_lines(const PlanFeature& feature, const class LocalProjection& projection,
                         std::vector<Ring>& out);

/// The centre of the features' bounding box in lon/lat (the local frame's origin).
Eigen::Vector2d plan_centre_lon_lat(const std::vector<PlanFeature>& features);

}  // namespace wifislam::floorplan
