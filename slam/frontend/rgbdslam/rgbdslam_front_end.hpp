#pragma once
// RGBD-SLAM's node selection (paper, "RGBD SLAM"; Endres et al., RGBDSLAMv2,
// GraphManager::getPotentialEdgeTargetsWithDijkstra): a new keyframe is compared with
//   (a) its predecessors, the most recent keyframes;
//   (b) geodesic neighbours: keyframes within `geodesic_depth` edges of the previous keyframe,
//       predecessors excluded, drawn without replacement with probability proportional to their
//       id distance from the previous keyframe (far ones are likelier: they close small loops);
//   (c) long-term candidates: earlier keyframes drawn uniformly (RGBDSLAMv2's "sampled"
//       candidates).
// (a) and (b) serve motion estimation, (c) long-term loop closure. Every keyframe stays
// searchable, and every verified comparison becomes an edge.
//
// Random draws: each group of each keyframe has its own sub-stream, (seed, group, keyframe id),
// so a vanilla and a Wi-Fi run of one dataset draw the same numbers wherever Wi-Fi does not act,
// and their first difference is where Wi-Fi first changed something.
//
// With a Wi-Fi module (paper, "RGBD SLAM", "Wi-Fi Augmentation": "we compare the current frame
// only to RGBD keyframes within similar clusters"), (a) and (b) stay as they are and (c) becomes:
//   - the pool: keyframes of the similar clusters that qualify as a loop closure (the pipeline's
//     LoopRule: keyframe gap and estimated path back);
//   - ranked by the cosine similarity of their own signature with the new keyframe's, best
//     first; ties (every keyframe of one pause shares its signature) are broken by a seeded draw
//     from the long-term sub-stream, which spreads the choice over the tied keyframes;
//   - at most RgbdslamOptions::wifi_long_term_candidates of them (default: vanilla's
//     `min_sampled_candidates`, so Wi-Fi never verifies more), none when no similar cluster has
//     a qualifying keyframe.
//   A keyframe made before the first scan has no Wi-Fi information: its long-term candidates are
//   drawn as in vanilla RGBD-SLAM, and it joins no cluster.

#include <cstdint>

#include "core/rng.hpp"
#include "slam/frontend/front_end.hpp"
#include "slam/frontend/rgbdslam/rgbdslam_options.hpp"

namespace wifislam::slam::frontend::rgbdslam {

class RgbdslamFrontEnd final : public FrontEnd {
 public:
  RgbdslamFrontEnd(const RgbdslamOptions& options, std::uint64_t seed);

  std::vector<Candidate> select(const SelectionQuery& query) override;

  const RgbdslamOptions& options() const { return options_; }

 protected:
  nlohmann::json own_summary() const override;

 private:
  /// Group (c): long-term candidates among `eligible` (earlier keyframes not chosen by (a) or
  /// (b), ascending ids).
  std::vector<graph::KeyframeId> long_term_candidates(
      const SelectionQuery& query, const std::vector<graph::KeyframeId>& eligible, Rng& rng);
  /// The Wi-Fi variant of (c).
  std::vector<graph::KeyframeId> wifi_long_term_candidates(
      const SelectionQuery& query, const std::vector<graph::KeyframeId>& eligible, Rng& rng);
  /// The sub-stream of one candidate group of one keyframe.
  Rng group_rng(const char* group, graph::KeyframeId keyframe) const;

  RgbdslamOptions options_;
  int wifi_long_term_candidates_;
  std::uint64_t seed_;
};

/// `count` distinct entries of `pool`, uniformly without replacement, in draw order.
std::vector<graph::KeyframeId> sample_without_replacement(
    const std::vector<graph::KeyframeId>& pool, int count, Rng& rng);

/// `count` distinct entries of `pool`, without replacement, each draw picking an entry with
/// probability proportional to its weight among those left (weights > 0), in draw order.
std::vector<graph::KeyframeId> sample_weighted_without_replacement(
    const std::vector<graph::KeyframeId>& pool, const std::vector<double>& weights, int count,
    Rng& rng);

}  // namespace wifislam::slam::frontend::rgbdslam
