#include "slam/frontend/rtabmap/likelihood.hpp"

#include <cmath>

namespace wifislam::slam::frontend::rtabmap {

RawLikelihood tf_idf_likelihood(const NodeWords& query, const std::vector<NodeId>& scored,
                                const VisualVocabulary& vocabulary,
                                const std::map<NodeId, NodeWords>& words_of,
                                std::size_t nodes_in_memory) {
  RawLikelihood out;
  for (NodeId j : scored) out.score.emplace(j, 0.0);
  if (scored.empty() || nodes_in_memory == 0) return out;
  const double n = static_cast<double>(nodes_in_memory);
  for (const auto& [word, count] : query.counts) {
    const std::map<NodeId, int>& refs = vocabulary.references(word);
    if (refs.empty()) continue;
    const double idf = std::log10(n / static_cast<double>(refs.size()));
    if (idf == 0.0) continue;
    for (const auto& [node, n_wj] : refs) {
      ++out.terms;
      const auto it = out.score.find(node);
      if (it == out.score.end()) continue;
      const int n_j = words_of.at(node).total;
      if (n_j > 0) it->second += static_cast<double>(n_wj) * idf / static_cast<double>(n_j);
    }
  }
  return out;
}

NormalisedLikelihood normalise_likelihood(const std::map<NodeId, double>& raw) {
  NormalisedLikelihood out;
  double sum = 0.0;
  int count = 0;
  for (const auto& [node, s] : raw) {
    if (s > 0) {
      sum += s;
      ++count;
    }
  }
  const double mean = count > 0 ? sum / count : 0.0;
  double var = 0.0;
  for (const auto& [node, s] : raw) {
    if (s > 0) var += (s - mean) * (s - mean);
  }
  const double stddev = count > 0 ? std::sqrt(var / count) : 0.0;
  out.mean = mean;
  out.stddev = stddev;
  constexpr double kEpsilon = 1e-4;
  bool raised = false;
  for (const auto& [node, s] : raw) {
    double l = 1.0;
    if (s > mean + stddev && mean > 0) {
      l = (s - (stddev - kEpsilon)) / mean;
      raised = true;
    }
    out.node.emplace(node, l);
  }
  out.virtual_place = stddev > kEpsilon && raised ? mean / stddev + 1.0 : 2.0;
  return out;
}

}  // namespace wifislam::slam::frontend::rtabmap
