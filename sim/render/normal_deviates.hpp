#pragma once
// Cheap standard normal deviates for per-pixel sensor noise (the depth and colour sensor models).
//
// Standard normal quantiles at 4096 evenly spaced probabilities, rescaled to unit variance: one
// 64-bit draw gives five normal deviates through a table lookup, and the 16 KiB table stays in
// L1 cache (a 2^16-entry table missed L2-resident lookups on every pixel). Rng::normal() costs
// ~10x more, and a 640x480 frame needs ~300k deviates inside a ~1 ms budget. The table has no
// values beyond +-3.7 sigma (a Kinect's noise has no heavy tails to lose either); the rescaling
// makes the standard deviation exact.

#include <array>

#include "core/rng.hpp"

namespace wifislam::sim::render {

inline constexpr int kNormalQuantileBits = 12;
using NormalQuantileTable = std::array<float, 1 << kNormalQuantileBits>;

/// The table: entry i is the quantile at probability (i + 0.5) / 4096, times a common factor
/// that makes the table's mean square exactly 1.
const NormalQuantileTable& normal_quantiles();

/// Fills `out[0..count)` with standard normal deviates from `rng`: five per 64-bit draw, then
/// one more draw for the rest (made even when nothing is left: pinned outputs rely on it).
void fill_normals(Rng& rng, float* out, int count);

}  // namespace wifislam::sim::render
