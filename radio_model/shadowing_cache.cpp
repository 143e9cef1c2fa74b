#include "radio_model/shadowing_cache.hpp"

#include <list>
#include <map>
#include <mutex>
#include <tuple>

#include <fmt/format.h>

namespace wifislam::radio_model {

namespace {

using GridKey = std::tuple<double, double, double, double, double, double>;
using FieldKey = std::tuple<GridKey, std::uint64_t, int, int>;

struct Cache {
  std::mutex mutex;
  std::map<GridKey, std::shared_ptr<const ShadowingGrid>> grids;
  std::list<FieldKey> recency;  // most recent first
  struct Entry {
    std::shared_ptr<const ShadowingField> field;
    std::list<FieldKey>::iterator position;
    std::size_t bytes;
  };
  std::map<FieldKey, Entry> fields;
  std::size_t bytes = 0;
};

Cache& cache() {
  static Cache c;
  return c;
}

}  // namespace

std::shared_ptr<const ShadowingField> shared_shadowing_field(
    const Eigen::Vector2d& min_m, const Eigen::Vector2d& max_m, double sigma_db,
    double decorrelation_m, std::uint64_t seed, int ap_id, int storey) {
  Cache& c = cache();
  const GridKey grid_key{min_m.x(), min_m.y(), max_m.x(), max_m.y(), sigma_db, decorrelation_m};
  const FieldKey key{grid_key, seed, ap_id, storey};
  std::shared_ptr<const ShadowingGrid> grid;
  {
    std::lock_guard lock(c.mutex);
    if (auto it = c.fields.find(key); it != c.fields.end()) {
      c.recency.splice(c.recency.begin(), c.recency, it->second.position);
      return it->second.field;
    }
    if (auto it = c.grids.find(grid_key); it != c.grids.end()) grid = it->second;
  }
  // Drawn outside the lock (two threads may draw the same field once each: same values).
  if (!grid) {
    grid = std::make_shared<const ShadowingGrid>(min_m, max_m, sigma_db, decorrelation_m);
    std::lock_guard lock(c.mutex);
    if (c.grids.size() > 16) c.grids.clear();  // a handful of sites per process
    c.grids.emplace(grid_key, grid);
  }
  auto field = std::make_shared<const ShadowingField>(grid->draw(
      Rng::stream(seed, storey == 0 ? fmt::format("shadowing/ap{}", ap_id)
                                    : fmt::format("shadowing/ap{}/storey{}", ap_id, storey))));
  const std::size_t bytes = field->memory_bytes();
  std::lock_guard lock(c.mutex);
  if (auto it = c.fields.find(key); it != c.fields.end()) return it->second.field;
  c.recency.push_front(key);
  c.fields.emplace(key, Cache::Entry{field, c.recency.begin(), bytes});
  c.bytes += bytes;
  while (c.bytes > kShadowingCacheBytes && c.recency.size() > 1) {
    const FieldKey oldest = c.recency.back();
    c.recency.pop_back();
    const auto it = c.fields.find(oldest);
    c.bytes -= it->second.bytes;
    c.fields.erase(it);
  }
  return field;
}

}  // namespace wifislam::radio_model
