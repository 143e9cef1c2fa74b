#include "radio_model/radio_map.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <thread>

#include <fmt/format.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/worker_pool.hpp"

namespace wifislam::radio_model {

namespace {

double ap_rssi(const PropagationModel& model, std::size_t a, const RadioLink& link,
               RadioMapBand band) {
  double best = -std::numeric_limits<double>::infinity();
  std::int64_t last_khz = -1;
  for (const Bssid& b : model.access_points()[a].bssids) {
    if (band == RadioMapBand::k2_4GHz && b.band != RadioBand::k2_4GHz) continue;
    if (band == RadioMapBand::k5GHz && b.band != RadioBand::k5GHz) continue;
    if (b.frequency_khz == last_khz) continue;  // BSSIDs of one radio share its channel
    last_khz = b.frequency_khz;
    best = std::max(best, model.mean_rssi_dbm(a, b, link));
  }
  return best;
}

/// An empty map over the area at the options' resolution. Throws InvalidInputError for a
/// resolution or height out of range, or a map over the size limits.
RadioMap empty_map(const RadioMapArea& area, const RadioMapOptions& options) {
  // At most 10 m a cell, as `radiomap --res` says: a coarser (or infinite) grid is no map.
  if (!(options.resolution_m > 0.0 && options.resolution_m <= kRadioMapMaxResolutionM))
    throw InvalidInputError(
        fmt::format("radio map resolution must be > 0 and at most {} m (got {})",
                    kRadioMapMaxResolutionM, options.resolution_m));
  if (!(options.receiver_height_m > 0.0 && options.receiver_height_m < area.ceiling_m)) {
    throw InvalidInputError(
        fmt::format("radio map: receiver height {} m is not between the floor and the ceiling "
                    "(0 to {} m)",
                    options.receiver_height_m, area.ceiling_m));
  }
  RadioMap map;
  map.origin_m = area.bounds_min_m;
  map.resolution_m = options.resolution_m;
  map.ap_id = options.ap_id;
  const Eigen::Vector2d extent = area.bounds_max_m - area.bounds_min_m;
  // Counted in doubles first: a tiny resolution once overflowed the int and gave a 1 x 1 map.
  const double cols = std::max(1.0, std::ceil(extent.x() / options.resolution_m));
  const double rows = std::max(1.0, std::ceil(extent.y() / options.resolution_m));
  if (cols > kRadioMapMaxSide || rows > kRadioMapMaxSide ||
      cols * rows > static_cast<double>(kRadioMapMaxCells)) {
    const double finest_m =
        std::max(std::sqrt(extent.x() * extent.y() / static_cast<double>(kRadioMapMaxCells)),
                 std::max(extent.x(), extent.y()) / kRadioMapMaxSide);
    throw InvalidInputError(fmt::format(
        "radio map: a resolution of {} m gives {:.0f} x {:.0f} cells over this {:.1f} x {:.1f} m "
        "plan; a map has at most {} million cells and {} a side, so use a resolution of at "
        "least {:.3g} m (--res)",
        options.resolution_m, cols, rows, extent.x(), extent.y(), kRadioMapMaxCells / 1'000'000,
        kRadioMapMaxSide, finest_m * 1.001));
  }
  map.cols = static_cast<int>(cols);
  map.rows = static_cast<int>(rows);
  const std::size_t cells = static_cast<std::size_t>(map.cols) * map.rows;
  map.rssi_dbm.assign(cells, std::numeric_limits<float>::quiet_NaN());
  map.best_ap_id.assign(cells, -1);
  return map;
}

/// The strongest access point at one receiver position: (RSSI, index), ties to the lowest index.
/// With `prune`, APs are tried in order of their wall-free RSSI (an upper bound) and the search
/// stops when the bound cannot beat the best so far: the same answer, fewer ray casts.
std::pair<double, std::size_t> strongest(const PropagationModel& model, const Eigen::Vector3d& rx,
                                         RadioMapBand band, std::optional<std::size_t> only,
                                         bool prune,
                                         std::vector<std::pair<double, std::size_t>>& bounds) {
  const std::size_t n = model.access_points().size();
  double best = -std::numeric_limits<double>::infinity();
  std::size_t best_index = n;
  const auto consider = [&](std::size_t a) {
    const double v = ap_rssi(model, a, model.link(a, rx), band);
    if (v > best || (v == best && a < best_index)) {
      best = v;
      best_index = a;
    }
  };
  if (only) {
    consider(*only);
  } else if (!prune) {
    for (std::size_t a = 0; a < n; ++a) consider(a);
  } else {
    bounds.clear();
    for (std::size_t a = 0; a < n; ++a)
      bounds.emplace_back(ap_rssi(model, a, model.link_without_walls(a, rx), band), a);
    std::sort(bounds.begin(), bounds.end(),
              [](const auto& x, const auto& y) { return x.first > y.first; });
    for (const auto& [bound, a] : bounds) {
      if (bound < best) break;
      consider(a);
    }
  }
  return {best, best_index};
}

}  // namespace

RadioMap compute_radio_map(const PropagationModel& model, const RadioMapArea& area,
                           const RadioMapOptions& options) {
  RadioMap map = empty_map(area, options);
  const auto& aps = model.access_points();
  if (aps.empty()) throw InvalidInputError("radio map: the scene has no access points");
  std::optional<std::size_t> only;
  if (options.ap_id) {
    only = model.index_of(*options.ap_id);
    if (!only)
      throw InvalidInputError(fmt::format("radio map: no access point with id {} (ids 0..{})",
                                          *options.ap_id, aps.size() - 1));
  }
  std::vector<bool> compute(map.rssi_dbm.size(), true);
  if (options.free_space_only && area.cells_to_compute) {
    compute = area.cells_to_compute(map);
    if (compute.size() != map.rssi_dbm.size())
      throw InvalidInputError(fmt::format("radio map: the area's mask has {} cells, the map {}",
                                          compute.size(), map.rssi_dbm.size()));
  }
  const bool prune = options.prune && model.walls_only_attenuate();
  // Rows on worker threads; every cell depends only on its own position, so any thread count
  // gives the same map.
  parallel_for(
      clamp_thread_count(options.threads), static_cast<std::size_t>(map.rows), [&](std::size_t r) {
        std::vector<std::pair<double, std::size_t>> bounds;
        for (int c = 0; c < map.cols; ++c) {
          const std::size_t i = r * static_cast<std::size_t>(map.cols) + c;
          if (!compute[i]) continue;
          const Eigen::Vector2d xy = map.cell_center_m(c, static_cast<int>(r));
          const Eigen::Vector3d rx(xy.x(), xy.y(),
                                   area.floor_elevation_m + options.receiver_height_m);
          const auto [best, index] = strongest(model, rx, options.band, only, prune, bounds);
          map.rssi_dbm[i] = static_cast<float>(best);
          map.best_ap_id[i] = index < aps.size() ? aps[index].id : -1;
        }
      });
  return map;
}

void write_radio_map_csv(const RadioMap& map, const std::filesystem::path& path) {
  std::string text = "x_m,y_m,rssi_dbm,ap_id\n";
  for (int r = 0; r < map.rows; ++r) {
    for (int c = 0; c < map.cols; ++c) {
      const Eigen::Vector2d p = map.cell_center_m(c, r);
      const std::size_t i = static_cast<std::size_t>(r) * map.cols + c;
      if (!std::isfinite(map.rssi_dbm[i])) continue;
      fmt::format_to(std::back_inserter(text), "{:.3f},{:.3f},{:.2f},{}\n", p.x(), p.y(),
                     map.rssi_dbm[i], map.best_ap_id[i]);
    }
  }
  write_file_atomic(path, text);
}

}  // namespace wifislam::radio_model
