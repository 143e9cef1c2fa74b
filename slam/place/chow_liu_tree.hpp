#pragma once
// The Chow-Liu tree over binary word observations, as openFABMAP's ChowLiuTree learns it
// (Chow and Liu 1968; Cummins and Newman 2008): the tree-shaped distribution closest to the
// training data, each word conditioned on one parent word.
//
//   marginal       P(z_q = 1) = 0.98 f_q + 0.01 (f_q: share of training observations with q)
//   conditional    P(z_q = 1 | z_p = b) = 0.98 n(q, p=b) / n(p=b) + 0.01 (0.01 without data)
//   edge weight    mutual information over the four cells, with the smoothed marginals and the
//                  raw joint frequencies (as openFABMAP computes it)
//   tree           maximum spanning tree of the weights (Boost.Graph's Kruskal on negated
//                  information), edges below `lower_info_bound` (openFABMAP's LowerInfoBound,
//                  0.0005) left out
//
// Where openFABMAP refuses (the kept edges do not span every word), each connected part is a tree
// of its own whose root has no parent: a word no edge reaches is independent (naive Bayes).
// Roots are the lowest word of their part, children found breadth first: the tree is a function
// of the data alone.

#include <string>
#include <vector>

#include "slam/place/binary_observation.hpp"

namespace wifislam::slam::place {

struct ChowLiuTree {
  /// parent[q]: the word q is conditioned on, q itself for a root.
  std::vector<int> parent;
  std::vector<double> p_present;                 // P(z_q = 1)
  std::vector<double> p_present_parent_present;  // P(z_q = 1 | z_parent = 1)
  std::vector<double> p_present_parent_absent;   // P(z_q = 1 | z_parent = 0)

  int word_count() const { return static_cast<int>(parent.size()); }
  /// Appends `count` independent words (roots) with the given marginals.
  void append_independent(const std::vector<double>& marginals);
  /// Text form: a header line, then "q parent p p|1 p|0" per word (17 significant digits, so a
  /// file reads back to the same doubles and retraining gives the same bytes).
  std::string serialise() const;
  static ChowLiuTree deserialise(const std::string& text, const std::string& source);
  // Stored inside FAB-MAP's training file (fabmap_training.hpp), not on its own.
};

inline constexpr double kLowerInfoBound = 0.0005;

/// The smoothed marginal of a word seen in `count` of `total` observations (0.98 f + 0.01).
double smoothed_marginal(std::size_t count, std::size_t total);

/// Learns the tree over `word_count` words from training observations.
ChowLiuTree learn_chow_liu_tree(const std::vector<BinaryObservation>& observations, int word_count,
                                double lower_info_bound = kLowerInfoBound);

/// Every word independent, with its smoothed marginal in `observations` (FAB-MAP's naive Bayes).
ChowLiuTree independent_words(const std::vector<BinaryObservation>& observations, int word_count);

}  // namespace wifislam::slam::place
