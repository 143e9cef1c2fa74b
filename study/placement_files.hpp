#pragma once
// What `wifislam study place` writes and prints for a greedy placement (greedy_placement.hpp):
//   placement.csv        one row per access point added: position, the greedy placement's
//                        error, resolution and shares, the random placements' medians
//   access_points.yaml   the chosen positions as a scene block (placement: explicit)
//   placement, error, resolution .png/.svg   the figures (placement_plot.cpp)

#include <filesystem>
#include <string>

#include "study/greedy_placement.hpp"

namespace wifislam::study {

/// Writes the three kinds of files into `folder` (which exists). `scene_path` names the scene in
/// access_points.yaml's header.
void write_placement_files(const PlacementResult& result, const PlacementOptions& options,
                           const std::string& scene_path, const std::string& scene_name,
                           const std::filesystem::path& folder);

/// The table of the steps (greedy against random) and the scene's own access points, as printed.
std::string placement_table(const PlacementResult& result);

}  // namespace wifislam::study
