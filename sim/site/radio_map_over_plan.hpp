#pragma once
// Radio maps over a floor plan: the plan's bounds, ceiling and free space as the area a radio map
// covers (radio_model/radio_map.hpp computes it), and the map drawn as a heat map over the plan's
// walls with the access points marked.

#include <filesystem>
#include <vector>

#include "radio_model/access_point.hpp"
#include "radio_model/propagation_model.hpp"
#include "radio_model/radio_map.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::site {

/// The plan's bounds, its wall height as the ceiling, and its free space rasterised by cairo (a
/// cell is computed when its centre is in free space; a plan without free space computes all).
/// `floor_elevation_m`: the plan's floor in the radio model's frame (a storey's elevation).
radio_model::RadioMapArea radio_map_area(const world::FloorPlan& plan,
                                         double floor_elevation_m = 0.0);

/// compute_radio_map over radio_map_area(plan, floor_elevation_m).
radio_model::RadioMap compute_radio_map(const radio_model::PropagationModel& model,
                                        const world::FloorPlan& plan,
                                        const radio_model::RadioMapOptions& options,
                                        double floor_elevation_m = 0.0);

/// Heat map PNG over the plan (free space coloured, walls dark, APs marked, colour bar), written
/// atomically. Cells below `floor_dbm` are left grey.
void write_radio_map_png(const radio_model::RadioMap& map, const world::FloorPlan& plan,
                         const std::vector<radio_model::AccessPoint>& access_points,
                         const std::filesystem::path& path, double floor_dbm = -92.0);

}  // namespace wifislam::sim::site
