#include "slam/place/fabmap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/error.hpp"
#include "core/rng.hpp"

namespace wifislam::slam::place {

namespace {

double p_z_given_e(const FabMapOptions& o, bool z, bool e) {
  const double p1 = e ? o.p_z_given_e : o.p_z_given_not_e;
  return z ? p1 : 1.0 - p1;
}

double p_marginal(const ChowLiuTree& t, int q, bool z) {
  const double p = t.p_present[static_cast<std::size_t>(q)];
  return z ? p : 1.0 - p;
}

double p_given_parent(const ChowLiuTree& t, int q, bool z, bool z_parent) {
  const auto u = static_cast<std::size_t>(q);
  const double p = z_parent ? t.p_present_parent_present[u] : t.p_present_parent_absent[u];
  return z ? p : 1.0 - p;
}

/// P(e_q | the place saw L_q): openFABMAP's InferBinary::PeqGLzq (naive, from the marginal).
double p_e_given_place(const ChowLiuTree& t, const FabMapOptions& o, int q, bool place_saw,
                       bool e) {
  const double alpha = p_z_given_e(o, place_saw, true) * p_marginal(t, q, true);
  const double beta = p_z_given_e(o, place_saw, false) * p_marginal(t, q, false);
  const double p1 = alpha / (alpha + beta);
  return e ? p1 : 1.0 - p1;
}

double logsumexp(double a, double b) {
  return a > b ? std::log1p(std::exp(b - a)) + a : std::log1p(std::exp(a - b)) + b;
}

}  // namespace

double word_likelihood(const ChowLiuTree& tree, const FabMapOptions& o, int q, bool z,
                       bool z_parent, bool place_saw) {
  if (o.naive_bayes) {  // InferBinary::PzqGL
    return p_e_given_place(tree, o, q, place_saw, false) * p_z_given_e(o, z, false) +
           p_e_given_place(tree, o, q, place_saw, true) * p_z_given_e(o, z, true);
  }
  // InferBinary::PzqGzpqL: for each state of e_q, P(z_q | e_q, z_p) by Bayes over z_q with the
  // tree's conditional as the prior.
  double p = 0.0;
  for (bool e : {false, true}) {
    const double alpha =
        p_marginal(tree, q, z) * p_z_given_e(o, !z, e) * p_given_parent(tree, q, !z, z_parent);
    const double beta =
        p_marginal(tree, q, !z) * p_z_given_e(o, z, e) * p_given_parent(tree, q, z, z_parent);
    p += p_e_given_place(tree, o, q, place_saw, e) * beta / (alpha + beta);
  }
  return p;
}

double full_log_likelihood(const ChowLiuTree& tree, const FabMapOptions& options,
                           const BinaryObservation& query, const BinaryObservation& place) {
  double log_p = 0.0;
  for (int q = 0; q < tree.word_count(); ++q) {
    const int parent = tree.parent[static_cast<std::size_t>(q)];
    log_p +=
        std::log(word_likelihood(tree, options, q, query.has(q), query.has(parent), place.has(q)));
  }
  return log_p;
}

FabMap::FabMap(ChowLiuTree tree, FabMapOptions options,
               const std::vector<BinaryObservation>& training)
    : tree_(std::move(tree)), options_(options) {
  if (training.empty()) throw InvalidInputError("FAB-MAP: no training observations");
  const int words = tree_.word_count();
  children_.resize(static_cast<std::size_t>(words));
  // FabMap2's terms: the change of log P(z_q | z_p, L) when the place saw q, by (z_q, z_p).
  const auto ratio = [&](int q, bool z, bool zp) {
    return std::log(word_likelihood(tree_, options_, q, z, zp, true) /
                    word_likelihood(tree_, options_, q, z, zp, false));
  };
  for (int q = 0; q < words; ++q) {
    d1_.push_back(ratio(q, false, false));
    d2_.push_back(ratio(q, false, true) - d1_.back());
    d3_.push_back(ratio(q, true, false) - d1_.back());
    d4_.push_back(ratio(q, true, true) - d1_.back());
    const int parent = tree_.parent[static_cast<std::size_t>(q)];
    if (parent != q) children_[static_cast<std::size_t>(parent)].push_back(q);
  }
  places_.inverted.resize(static_cast<std::size_t>(words));
  samples_.inverted.resize(static_cast<std::size_t>(words));
  // The new-place sample: a seeded draw without replacement (a partial Fisher-Yates shuffle).
  std::vector<std::size_t> order(training.size());
  std::iota(order.begin(), order.end(), 0);
  const std::size_t n =
      std::min(order.size(), static_cast<std::size_t>(std::max(1, options_.new_place_samples)));
  Rng rng = Rng::stream(options_.seed, "fabmap/new_place_samples");
  for (std::size_t i = 0; i < n; ++i) {
    const auto j = static_cast<std::size_t>(
        rng.uniform_int(static_cast<std::int64_t>(i), static_cast<std::int64_t>(order.size() - 1)));
    std::swap(order[i], order[j]);
    add_to_index(samples_, training[order[i]]);
  }
}

void FabMap::add_to_index(Index& index, const BinaryObservation& observation) const {
  const int id = static_cast<int>(index.defaults.size());
  double sum = 0.0;
  for (int q : observation.present) {
    if (q < 0 || q >= tree_.word_count()) {
      throw InvalidInputError("FAB-MAP: word " + std::to_string(q) + " outside the tree");
    }
    sum += d1_[static_cast<std::size_t>(q)];
    index.inverted[static_cast<std::size_t>(q)].push_back(id);
  }
  index.defaults.push_back(sum);
}

int FabMap::add_place(const BinaryObservation& observation) {
  add_to_index(places_, observation);
  return place_count() - 1;
}

std::vector<double> FabMap::index_log_likelihoods(const Index& index,
                                                  const BinaryObservation& query) const {
  std::vector<double> out = index.defaults;
  for (int q : query.present) {
    if (q < 0 || q >= tree_.word_count()) continue;
    const auto u = static_cast<std::size_t>(q);
    const double term = query.has(tree_.parent[u]) ? d4_[u] : d3_[u];
    for (int id : index.inverted[u]) out[static_cast<std::size_t>(id)] += term;
    for (int child : children_[u]) {
      if (query.has(child)) continue;
      const auto c = static_cast<std::size_t>(child);
      for (int id : index.inverted[c]) out[static_cast<std::size_t>(id)] += d2_[c];
    }
  }
  return out;
}

std::vector<double> FabMap::place_log_likelihoods(const BinaryObservation& query) const {
  return index_log_likelihoods(places_, query);
}

double FabMap::new_place_log_likelihood(const BinaryObservation& query) const {
  const std::vector<double> samples = index_log_likelihoods(samples_, query);
  double sum = -std::numeric_limits<double>::infinity();
  for (double l : samples) sum = std::isinf(sum) ? l : logsumexp(sum, l);
  return sum - std::log(static_cast<double>(samples.size()));
}

std::vector<PlaceMatch> FabMap::match(const BinaryObservation& query,
                                      const std::vector<int>& candidates) const {
  const std::vector<double> all = place_log_likelihoods(query);
  std::vector<PlaceMatch> out = {{-1, new_place_log_likelihood(query), 0.0}};
  if (candidates.empty()) {
    for (int i = 0; i < place_count(); ++i)
      out.push_back({i, all[static_cast<std::size_t>(i)], 0.0});
  } else {
    for (int i : candidates) out.push_back({i, all.at(static_cast<std::size_t>(i)), 0.0});
  }
  double norm = out.front().log_likelihood;
  for (std::size_t i = 1; i < out.size(); ++i) norm = logsumexp(norm, out[i].log_likelihood);
  const double uniform = (1.0 - options_.smoothing) / static_cast<double>(out.size());
  for (PlaceMatch& m : out) {
    m.probability = options_.smoothing * std::exp(m.log_likelihood - norm) + uniform;
  }
  return out;
}

}  // namespace wifislam::slam::place
