#pragma once
// RGBD-SLAM's node selection (paper, "RGBD SLAM"; Endres et al., RGBDSLAMv2): a new keyframe is
// compared with (a) its predecessors, (b) a sample of its geodesic neighbours in the graph and
// (c) a random sample of earlier keyframes. (a) and (b) serve motion estimation, (c) long-term
// loop closure. Every keyframe stays searchable, and every verified comparison becomes an edge.
//
// With a Wi-Fi module (paper, "RGBD SLAM", "Wi-Fi Augmentation"), (a) and (b) stay as they are;
// the long-term candidates (c) are drawn only from keyframes of clusters similar to the new
// keyframe's signature (bounding loop-closure search). Choices where the paper is silent:
// - The number drawn is WifiOptions::sampled_candidates (default: vanilla's
//   `min_sampled_candidates`), uniformly from the bounded pool; 0 takes the whole pool.
// - The pool leaves out the last `loop_min_keyframe_gap` keyframes: a match with one of them is
//   an ordinary visual edge, not a loop closure, and predecessors/neighbours already cover them.
// - A keyframe made before the first scan has no Wi-Fi information: its long-term candidates are
//   drawn as in vanilla RGBD-SLAM, and it joins no cluster.

#include <cstdint>

#include "core/rng.hpp"
#include "slam/frontend/front_end.hpp"

namespace wifislam::slam {

/// Defaults are RGBDSLAMv2's.
struct RgbdslamOptions {
  /// The most recent keyframes compared with every new keyframe (`predecessor_candidates` 2).
  int predecessor_candidates = 2;
  /// Keyframes sampled among the geodesic neighbours of the previous keyframe
  /// (`neighbor_candidates` 2) within `geodesic_depth` edges (3). After a loop closure these
  /// reach back to the revisited place, which keeps the loop "closed" from then on.
  int neighbor_candidates = 2;
  int geodesic_depth = 3;
  /// Random earlier keyframes per new keyframe (`min_sampled_candidates` 2): the only source of
  /// long-term loop closures; the chance of drawing the right one falls as the map grows.
  int min_sampled_candidates = 2;
};

class RgbdslamFrontEnd final : public FrontEnd {
 public:
  /// Random draws come from Rng::stream(seed, "slam/rgbdslam/candidates"), and the Wi-Fi
  /// variant's long-term draws from Rng::stream(seed, "slam/wifi/candidates").
  /// `wifi_long_term_candidates`: long-term candidates drawn from the bounded pool when a Wi-Fi
  /// module is attached (0 = the whole pool).
  RgbdslamFrontEnd(const RgbdslamOptions& options, int wifi_long_term_candidates,
                   std::uint64_t seed);

  std::string name() const override { return "rgbdslam"; }
  std::vector<Candidate> select(const SelectionQuery& query) override;

  const RgbdslamOptions& options() const { return options_; }

 protected:
  nlohmann::json own_summary() const override;

 private:
  /// Group (c): long-term candidates among `eligible` (earlier keyframes not chosen by (a) or
  /// (b), ascending ids).
  std::vector<KeyframeId> long_term_candidates(const SelectionQuery& query,
                                               const std::vector<KeyframeId>& eligible);

  RgbdslamOptions options_;
  int wifi_long_term_candidates_;
  Rng rng_;
  Rng wifi_rng_;
};

/// `count` distinct entries of `pool`, uniformly without replacement, in draw order.
std::vector<KeyframeId> sample_without_replacement(const std::vector<KeyframeId>& pool, int count,
                                                   Rng& rng);

}  // namespace wifislam::slam
