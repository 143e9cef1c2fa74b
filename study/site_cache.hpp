#pragma once
// Sites shared by the radio-level cases of a study. Cases that differ only in their access points
// (count, placement, power: the usual axes of a placement study) have the same building, route
// and seed, so one world and one robot motion serve all of them: the first such case builds its
// site in full, the others get Site::with_access_points of it, which builds the radio model for
// their own access points exactly as Site(their scene) would (sim/site/site.hpp). So a case's
// results do not depend on which cases ran before it, or on whether any did.
//
// Keyed by the resolved scene file with the access_points block reset; bounded (kSiteCacheSize
// buildings, least recently used dropped: a study sweeps a handful of seeds and buildings).
// Thread-safe; two threads asking for a new building at once may both build it (same result).

#include <cstddef>
#include <memory>

#include "sim/scene/scene.hpp"
#include "sim/site/site.hpp"

namespace wifislam::study {

inline constexpr std::size_t kSiteCacheSize = 8;

/// The site of `scene`, built on a cached world and motion when an earlier scene had the same
/// building, route and seed.
std::shared_ptr<const sim::site::Site> shared_site(const sim::scene::Scene& scene);

}  // namespace wifislam::study
