#pragma once
// RGBD-SLAM's node selection (paper, "RGBD SLAM"; Endres et al., RGBDSLAMv2): a new keyframe is
// compared with (a) its predecessors, (b) a sample of its geodesic neighbours in the graph and
// (c) a random sample of earlier keyframes. (a) and (b) serve motion estimation, (c) long-term
// loop closure. A Wi-Fi variant replaces (c) by overriding long_term_candidates().

#include <cstdint>

#include "core/rng.hpp"
#include "slam/loop/candidate_selector.hpp"

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

class RgbdslamCandidateSelector : public CandidateSelector {
 public:
  /// Random draws come from Rng::stream(seed, "slam/rgbdslam/candidates").
  RgbdslamCandidateSelector(const RgbdslamOptions& options, std::uint64_t seed);

  std::string name() const override { return "rgbdslam"; }
  std::vector<Candidate> select(const SelectionQuery& query) final;

  const RgbdslamOptions& options() const { return options_; }

 protected:
  /// Group (c): long-term candidates among `eligible` (earlier keyframes not chosen by (a) or
  /// (b), ascending ids). Default: `min_sampled_candidates` drawn uniformly without replacement.
  virtual std::vector<KeyframeId> long_term_candidates(const SelectionQuery& query,
                                                       const std::vector<KeyframeId>& eligible);
  Rng& rng() { return rng_; }

 private:
  RgbdslamOptions options_;
  Rng rng_;
};

/// `count` distinct entries of `pool`, uniformly without replacement, in draw order.
std::vector<KeyframeId> sample_without_replacement(const std::vector<KeyframeId>& pool, int count,
                                                   Rng& rng);

}  // namespace wifislam::slam
