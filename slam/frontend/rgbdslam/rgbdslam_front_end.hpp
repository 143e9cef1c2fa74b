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

namespace wifislam::slam {

/// Defaults are RGBDSLAMv2's current ones (parameter_server.cpp, since 2015): 4 / 4 / 4. Its
/// defaults before 2015 were 2 / 2 / 2 (`--set predecessor_candidates=2 --set
/// neighbor_candidates=2 --set min_sampled_candidates=2`).
struct RgbdslamOptions {
  /// The most recent keyframes compared with every new keyframe (`predecessor_candidates`).
  int predecessor_candidates = 4;
  /// Keyframes sampled among the geodesic neighbours of the previous keyframe
  /// (`neighbor_candidates`) within `geodesic_depth` edges (3). After a loop closure these
  /// reach back to the revisited place, which keeps the loop "closed" from then on.
  int neighbor_candidates = 4;
  int geodesic_depth = 3;
  /// Random earlier keyframes per new keyframe (`min_sampled_candidates`): the only source of
  /// long-term loop closures; the chance of drawing the right one falls as the map grows.
  int min_sampled_candidates = 4;
  /// With a Wi-Fi module: long-term candidates taken from the ranked pool of similar clusters.
  /// -1 = `min_sampled_candidates` (Wi-Fi never verifies more than vanilla); 0 = the whole pool
  /// (exhaustive: the costliest reading of "compare the current frame only to keyframes within
  /// similar clusters").
  int wifi_long_term_candidates = -1;

  /// The robust back end (RGBDSLAMv2 GraphManager: a Huber kernel on every edge; at the end of a
  /// run, edges over chi^2 5, then 1, then 0.25 pruned with a re-optimisation after each).
  ///
  /// RGBDSLAMv2's information is not calibrated (inliers / rmse^2 x identity, rmse a unitless 3-D
  /// Mahalanobis distance), so its numbers cannot be carried over: on our information, whose
  /// chi^2 follows chi^2(6) for correct edges (docs: README, "Robust back end"), a threshold of
  /// 0.25 would prune every edge. We keep its schedule's shape, 20 : 4 : 1 with the kernel at 4x
  /// the last stage, and anchor the last stage at the 99.9 % quantile of chi^2(6) (22.46): an
  /// edge measured as well as it claims is pruned with probability 0.1 %.
  std::string robust_kernel = "huber";           // none, huber, cauchy
  double robust_kernel_chi2 = 4 * 22.46;         // where the kernel leaves the quadratic
  std::string prune_chi2 = "449.2,89.84,22.46";  // stages, comma-separated; "none": no pruning

  /// Incremental optimisation after every n-th keyframe, besides after each keyframe that brought
  /// a loop closure (RGBDSLAMv2's `optimizer_skip_step`, default 1). 0: after loop closures only.
  int optimizer_skip_step = 1;
  /// How far each incremental optimisation goes (RGBDSLAMv2's `optimizer_iterations`, default
  /// 0.01, which below 1 means: GraphManager::optimizeGraphImpl runs rounds of 5 iterations
  /// until a round lowers the graph's chi^2 by less than this fraction, at least two rounds and
  /// no cap). A graph torn between conflicting edges takes more rounds than a consistent one.
  /// Ours caps the rounds at `optimizer_iterations` (the final optimisation's, 100) as a guard.
  /// 0: at most `optimizer_incremental_iterations`, the pipeline's fixed budget.
  double optimizer_convergence = 0.01;
};

class RgbdslamFrontEnd final : public FrontEnd {
 public:
  RgbdslamFrontEnd(const RgbdslamOptions& options, std::uint64_t seed);

  std::string name() const override { return "rgbdslam"; }
  std::vector<Candidate> select(const SelectionQuery& query) override;
  GraphRobustness graph_robustness() const override;
  int optimise_every_keyframes() const override { return options_.optimizer_skip_step; }
  double optimisation_convergence() const override { return options_.optimizer_convergence; }

  const RgbdslamOptions& options() const { return options_; }

 protected:
  nlohmann::json own_summary() const override;

 private:
  /// Group (c): long-term candidates among `eligible` (earlier keyframes not chosen by (a) or
  /// (b), ascending ids).
  std::vector<KeyframeId> long_term_candidates(const SelectionQuery& query,
                                               const std::vector<KeyframeId>& eligible, Rng& rng);
  /// The Wi-Fi variant of (c).
  std::vector<KeyframeId> wifi_long_term_candidates(const SelectionQuery& query,
                                                    const std::vector<KeyframeId>& eligible,
                                                    Rng& rng);
  /// The sub-stream of one candidate group of one keyframe.
  Rng group_rng(const char* group, KeyframeId keyframe) const;

  RgbdslamOptions options_;
  int wifi_long_term_candidates_;
  std::uint64_t seed_;
};

/// `count` distinct entries of `pool`, uniformly without replacement, in draw order.
std::vector<KeyframeId> sample_without_replacement(const std::vector<KeyframeId>& pool, int count,
                                                   Rng& rng);

/// `count` distinct entries of `pool`, without replacement, each draw picking an entry with
/// probability proportional to its weight among those left (weights > 0), in draw order.
std::vector<KeyframeId> sample_weighted_without_replacement(const std::vector<KeyframeId>& pool,
                                                            const std::vector<double>& weights,
                                                            int count, Rng& rng);

}  // namespace wifislam::slam
