#pragma once
// Shadowing fields shared by every propagation model of the process. A field depends only on the
// site's rectangle, sigma, decorrelation distance, the seed and the AP's id (its stream
// "shadowing/ap<id>"), so models of one site that differ in the number, placement or power of
// their access points (a study's cases, a greedy placement's trials) draw each AP's field once.
// The fields are immutable and exactly those an uncached model would draw.
//
// Bounded: fields beyond kCacheBytes, least recently used first, are dropped (a model keeps its
// own fields alive through shared pointers).

#include <cstddef>
#include <cstdint>
#include <memory>

#include <Eigen/Core>

#include "radio_model/shadowing_field.hpp"

namespace wifislam::radio_model {

inline constexpr std::size_t kShadowingCacheBytes = std::size_t{256} << 20;

/// The field of AP `ap_id` over [min_m, max_m] on storey `storey`, drawn from
/// Rng::stream(seed, "shadowing/ap<id>") for the lowest storey (and a one-storey building) and
/// from "shadowing/ap<id>/storey<k>" for storey k > 0.
std::shared_ptr<const ShadowingField> shared_shadowing_field(
    const Eigen::Vector2d& min_m, const Eigen::Vector2d& max_m, double sigma_db,
    double decorrelation_m, std::uint64_t seed, int ap_id, int storey = 0);

}  // namespace wifislam::radio_model
