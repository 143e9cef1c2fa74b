#pragma once
// Radio maps: the mean RSSI (shadowing included, no fading) on a regular grid over an area (the
// floor plan's bounds), for one access point or for the strongest one at each cell; written as
// CSV here, drawn over the plan by the simulator (sim/site/radio_map_over_plan.hpp).
//
// Computed row by row on worker threads; every cell depends only on its own position, so the map
// is identical whatever the thread count.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "radio_model/propagation_model.hpp"

namespace wifislam::radio_model {

enum class RadioMapBand { kBest, k2_4GHz, k5GHz };

struct RadioMapOptions {
  double resolution_m = 0.25;
  /// Where datasets scan: pass Site::receiver_height_m() (the camera height; 0.5 m by default).
  double receiver_height_m = 0.5;
  std::optional<int> ap_id;                 // nullopt: the strongest AP at every cell
  RadioMapBand band = RadioMapBand::kBest;  // best: the AP's stronger radio
  int threads = 0;                          // 0: all hardware threads
  /// Compute only the area's cells_to_compute, its free space (others are NaN): the map is
  /// drawn over free space only, and a loop building's courtyard and the walls are a large part
  /// of its bounding box.
  bool free_space_only = true;
  /// Strongest-AP maps: skip the wall ray for an AP whose wall-free RSSI (an upper bound) cannot
  /// beat the best found so far. Exact: the map is identical with and without.
  bool prune = true;
};

struct RadioMap {
  Eigen::Vector2d origin_m = Eigen::Vector2d::Zero();  // lower-left corner of cell (0, 0)
  double resolution_m = 0.25;
  int cols = 0, rows = 0;
  std::optional<int> ap_id;
  std::vector<float> rssi_dbm;  // row-major, row 0 at the lowest y; NaN = not computed
  std::vector<int> best_ap_id;  // the AP giving each cell's value
  Eigen::Vector2d cell_center_m(int col, int row) const {
    return origin_m + resolution_m * Eigen::Vector2d(col + 0.5, row + 0.5);
  }
  float at(int col, int row) const { return rssi_dbm[static_cast<std::size_t>(row) * cols + col]; }
};

/// Where a map is computed: the rectangle it covers, the ceiling a receiver must stay under, and
/// which cells of the grid lie in free space (row-major, as RadioMap::rssi_dbm; unset: all).
struct RadioMapArea {
  Eigen::Vector2d bounds_min_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d bounds_max_m = Eigen::Vector2d::Zero();
  double ceiling_m = 0.0;
  /// The floor the receiver height is measured from, in the model's frame (a storey's
  /// elevation in a building of several; 0 for one).
  double floor_elevation_m = 0.0;
  std::function<std::vector<bool>(const RadioMap& grid)> cells_to_compute;
};

/// The largest map: 16 million cells (about 150 MB with its picture), at most 16384 a side (the
/// picture is a cairo surface, which takes at most 32767).
inline constexpr std::int64_t kRadioMapMaxCells = 16'000'000;
inline constexpr int kRadioMapMaxSide = 16384;
/// The coarsest cell (`radiomap --res` takes 0.01 to 10 m).
inline constexpr double kRadioMapMaxResolutionM = 10.0;

/// Throws InvalidInputError for an unknown ap_id, a resolution not in (0, kRadioMapMaxResolutionM]
/// or one that needs more cells than kRadioMapMaxCells or kRadioMapMaxSide, a receiver height not
/// under the ceiling, or a model without access points.
RadioMap compute_radio_map(const PropagationModel& model, const RadioMapArea& area,
                           const RadioMapOptions& options);

/// CSV "x_m,y_m,rssi_dbm,ap_id" (cell centres of the computed cells), written atomically.
void write_radio_map_csv(const RadioMap& map, const std::filesystem::path& path);

}  // namespace wifislam::radio_model
