#pragma once
// RTAB-Map's loop-closure likelihood (Labbé & Michaud 2013, section III-D;
// Memory::computeLikelihood and Rtabmap::adjustLikelihood).
//
// Raw score, tf-idf over the inverted index (Kp/TfIdfLikelihoodUsed, the default): for every
// distinct word w of the new node and every node j in memory referencing it,
//     s_j += n_wj * log10(N / n_w) / n_j
// with n_wj the times w occurs in j, n_j the words of j, n_w the nodes referencing w and N the
// nodes in memory (STM + WM). Only the scored nodes (WM, or its Wi-Fi bound) accumulate.
//
// Normalisation (Angeli's, as RTAB-Map applies it): with mean mu and standard deviation sigma of
// the non-zero raw scores,
//     l_j = (s_j - (sigma - 1e-4)) / mu   when s_j > mu + sigma (and mu > 0), else 1;
//     l_virtual = mu / sigma + 1          when sigma > 1e-4 and some l_j was raised, else 2.
// (Labbé 2013 writes the same rule as (s_j - sigma) / mu for s_j >= mu + sigma.) The virtual place
// is the hypothesis "no loop closure": a flat likelihood leaves it the most likely.

#include <cstdint>
#include <map>
#include <vector>

#include "slam/frontend/rtabmap/visual_vocabulary.hpp"

namespace wifislam::slam::frontend::rtabmap {

struct RawLikelihood {
  std::map<NodeId, double> score;  // every scored node, 0 when it shares no word
  /// Work: inverted-index references visited (the cost model's likelihood terms).
  std::int64_t terms = 0;
};

/// Raw tf-idf scores of `query` against `scored` (ascending ids). `words_of(j)` gives a scored
/// node's words; `nodes_in_memory` is N.
RawLikelihood tf_idf_likelihood(const NodeWords& query, const std::vector<NodeId>& scored,
                                const VisualVocabulary& vocabulary,
                                const std::map<NodeId, NodeWords>& words_of,
                                std::size_t nodes_in_memory);

struct NormalisedLikelihood {
  double virtual_place = 1.0;
  std::map<NodeId, double> node;  // same keys as the raw scores
  double mean = 0.0, stddev = 0.0;
};

NormalisedLikelihood normalise_likelihood(const std::map<NodeId, double>& raw);

}  // namespace wifislam::slam::frontend::rtabmap
