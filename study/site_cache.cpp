#include "study/site_cache.hpp"

#include <list>
#include <mutex>
#include <string>
#include <utility>

#include "core/atomic_file.hpp"
#include "sim/scene/scene_loader.hpp"

namespace wifislam::study {

namespace {

struct Cache {
  std::mutex mutex;
  std::list<std::pair<std::string, std::shared_ptr<const sim::site::Site>>>
      entries;  // recent first
};

Cache& cache() {
  static Cache c;
  return c;
}

std::string building_key(const sim::scene::Scene& scene) {
  sim::scene::Scene without_aps = scene;
  without_aps.access_points = sim::scene::AccessPoints{};
  return sha256_hex(sim::scene::resolved_scene_yaml(without_aps));
}

}  // namespace

std::shared_ptr<const sim::site::Site> shared_site(const sim::scene::Scene& scene) {
  const std::string key = building_key(scene);
  Cache& c = cache();
  std::shared_ptr<const sim::site::Site> base;
  {
    std::lock_guard lock(c.mutex);
    for (auto it = c.entries.begin(); it != c.entries.end(); ++it) {
      if (it->first != key) continue;
      c.entries.splice(c.entries.begin(), c.entries, it);
      base = it->second;
      break;
    }
  }
  if (base)
    return std::make_shared<const sim::site::Site>(base->with_access_points(scene.access_points));
  auto site = std::make_shared<const sim::site::Site>(scene);
  std::lock_guard lock(c.mutex);
  c.entries.emplace_front(key, site);
  if (c.entries.size() > kSiteCacheSize) c.entries.pop_back();
  return site;
}

}  // namespace wifislam::study
