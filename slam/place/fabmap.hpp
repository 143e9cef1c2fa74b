#pragma once
// FAB-MAP's place recognition (Cummins and Newman 2008, 2011) as openFABMAP's FabMap2 computes it,
// so that our numbers mean what theirs mean:
//
//   detector model   P(z = 1 | e = 1) = PzGe (0.39), P(z = 1 | e = 0) = PzGNe (0): a word the
//                    scene holds is seen with probability 0.39, a word it lacks never
//   generator        P(e_q = 1 | place) from the place's one stored observation and the word's
//                    marginal (openFABMAP's InferBinary::PeqGLzq). openFABMAP's generator posterior
//                    is always naive Bayes, also with the Chow-Liu tree (openfabmap issue 1); we
//                    follow it, so the tree enters only through the observation term
//   observation      P(z_q | z_parent(q), place), summed over e_q (InferBinary::PzqGzpqL), or
//                    P(z_q | place) with naive Bayes (PzqGL)
//   new place        the mean likelihood of `new_place_samples` training observations (drawn
//                    without replacement from a seeded stream; all of them when fewer),
//                    the sampled term of FabMap2 (whose sample is every training observation)
//   posterior        likelihoods normalised over {new place, map places}, then smoothed:
//                    0.99 p + 0.01 / (places + 1) (FabMap::normaliseDistribution, no motion prior)
//
// Likelihoods are kept as FabMap2 keeps them: log P(Z | L) minus log P(Z | a place that saw no
// word), a constant of the query that cancels in the posterior, computed from an inverted index
// in time proportional to the words the query and the places share.

#include <cstdint>
#include <vector>

#include "slam/place/binary_observation.hpp"
#include "slam/place/chow_liu_tree.hpp"

namespace wifislam::slam::place {

struct FabMapOptions {
  double p_z_given_e = 0.39;     // openFABMAP's PzGe (sample settings)
  double p_z_given_not_e = 0.0;  // PzGNe
  double smoothing = 0.99;       // sFactor
  int new_place_samples = 3000;  // NumSamples
  bool naive_bayes = false;      // ignore the tree's parents
  std::uint64_t seed = 1;        // the new-place sample's draw
};

/// P(z_q | z_parent, place saw L) for one word, as openFABMAP's InferBinary (tests check it by
/// hand).
double word_likelihood(const ChowLiuTree& tree, const FabMapOptions& options, int q, bool z,
                       bool z_parent, bool place_saw);

/// log P(Z | L) summed over every word (FabMap1's direct form; for tests and small vocabularies).
double full_log_likelihood(const ChowLiuTree& tree, const FabMapOptions& options,
                           const BinaryObservation& query, const BinaryObservation& place);

struct PlaceMatch {
  int place = -1;             // index in the map, -1 for a new place
  double log_likelihood = 0;  // relative (see above)
  double probability = 0;     // smoothed posterior
};

class FabMap {
 public:
  /// `training`: the observations the new-place term samples (never the map's).
  FabMap(ChowLiuTree tree, FabMapOptions options, const std::vector<BinaryObservation>& training);

  /// Adds a map place; returns its index.
  int add_place(const BinaryObservation& observation);
  int place_count() const { return static_cast<int>(places_.defaults.size()); }

  /// The posterior over {new place, `candidates`} (all places when empty), new place first, then
  /// the candidates in the order given.
  std::vector<PlaceMatch> match(const BinaryObservation& query,
                                const std::vector<int>& candidates = {}) const;

  /// Relative log-likelihoods of `query` for every map place (index order).
  std::vector<double> place_log_likelihoods(const BinaryObservation& query) const;
  double new_place_log_likelihood(const BinaryObservation& query) const;

 private:
  struct Index {
    std::vector<double> defaults;            // per observation: sum of d1 over its words
    std::vector<std::vector<int>> inverted;  // per word: observations holding it
  };
  void add_to_index(Index& index, const BinaryObservation& observation) const;
  std::vector<double> index_log_likelihoods(const Index& index,
                                            const BinaryObservation& query) const;

  ChowLiuTree tree_;
  FabMapOptions options_;
  std::vector<double> d1_, d2_, d3_, d4_;  // FabMap2's per-word log-ratio terms
  std::vector<std::vector<int>> children_;
  Index places_, samples_;
};

}  // namespace wifislam::slam::place
