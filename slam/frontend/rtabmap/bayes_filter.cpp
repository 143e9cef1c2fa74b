#include "slam/frontend/rtabmap/bayes_filter.hpp"

#include <numeric>
#include <sstream>

#include "core/error.hpp"

namespace wifislam::slam::frontend::rtabmap {

std::vector<double> parse_prediction_lc(const std::string& key, const std::string& text) {
  std::istringstream in(text);
  std::vector<double> values;
  std::string token;
  while (in >> token) {
    double v = 0;
    try {
      std::size_t used = 0;
      v = std::stod(token, &used);
      if (used != token.size()) throw std::invalid_argument(token);
    } catch (const std::exception&) {
      throw InvalidInputError("SLAM option " + key + ": '" + token + "' is not a number");
    }
    if (!(v >= 0)) throw InvalidInputError("SLAM option " + key + ": values must be >= 0");
    values.push_back(v);
  }
  if (values.size() < 2) {
    throw InvalidInputError("SLAM option " + key +
                            " needs at least two values (virtual place, loop closure)");
  }
  return values;
}

BayesFilter::BayesFilter(std::vector<double> prediction_lc, double virtual_place_prior)
    : prediction_lc_(std::move(prediction_lc)),
      total_(std::accumulate(prediction_lc_.begin(), prediction_lc_.end(), 0.0)),
      virtual_place_prior_(virtual_place_prior) {}

void BayesFilter::update(const std::map<NodeId, double>& likelihood, double virtual_likelihood,
                         const NeighbourFunction& neighbours) {
  // The last posterior over this update's hypotheses (BayesFilter::updatePosterior).
  const bool first = posterior_.empty();
  std::map<NodeId, double> last;
  const auto carried = [&](NodeId id) {
    if (first) return 1.0;
    const auto it = posterior_.find(id);
    return it == posterior_.end() ? 0.0 : it->second;
  };
  last[kVirtualPlace] = carried(kVirtualPlace);
  for (const auto& [id, l] : likelihood) last[id] = carried(id);

  // prior = prediction x last, one column at a time.
  std::map<NodeId, double> prior;
  for (const auto& [id, p] : last) prior[id] = 0.0;
  const std::size_t cols = last.size();
  const double lc0 = prediction_lc_[0];
  for (const auto& [from, p_from] : last) {
    if (p_from == 0.0) continue;
    if (from == kVirtualPlace) {
      if (cols == 1) {
        prior[kVirtualPlace] += p_from;
        continue;
      }
      prior[kVirtualPlace] += virtual_place_prior_ * p_from;
      const double spread = (1.0 - virtual_place_prior_) / static_cast<double>(cols - 1);
      for (auto& [id, value] : prior) {
        if (id != kVirtualPlace) value += spread * p_from;
      }
      continue;
    }
    std::map<NodeId, double> column;
    double added = 0.0;
    for (const auto& [id, margin] : neighbours(from, max_margin())) {
      if (margin < 0 || margin > max_margin() || !likelihood.contains(id)) continue;
      const double v = prediction_lc_[static_cast<std::size_t>(margin) + 1];
      column[id] = v;
      added += v;
    }
    // What the model gives to neighbours that are no hypotheses goes to the node itself.
    if (added < total_ - lc0) {
      column[from] += total_ - lc0 - added;
      added = total_ - lc0;
    }
    // A model summing below 1 spreads the rest over every other hypothesis.
    double rest = 0.0;
    if (total_ < 1.0 && cols > 1) rest = (1.0 - total_) / static_cast<double>(cols - 1);
    if (rest > 0.0) {
      for (const auto& [id, l] : likelihood) {
        if (!column.contains(id)) {
          column[id] = rest;
          added += rest;
        }
      }
    }
    const double scale = added > 0 ? (1.0 - lc0) / added : 0.0;
    for (const auto& [id, v] : column) prior[id] += v * scale * p_from;
    prior[kVirtualPlace] += lc0 * p_from;
  }

  // posterior = likelihood .* prior, normalised.
  posterior_.clear();
  double sum = 0.0;
  for (const auto& [id, pr] : prior) {
    const double l = id == kVirtualPlace ? virtual_likelihood : likelihood.at(id);
    posterior_[id] = l * pr;
    sum += l * pr;
  }
  if (sum > 0) {
    for (auto& [id, p] : posterior_) p /= sum;
  } else {
    // Nothing carried probability (cannot happen with a virtual place prior > 0): start over.
    for (auto& [id, p] : posterior_) p = id == kVirtualPlace ? 1.0 : 0.0;
  }
}

double BayesFilter::virtual_probability() const {
  const auto it = posterior_.find(kVirtualPlace);
  return it == posterior_.end() ? 1.0 : it->second;
}

std::pair<NodeId, double> BayesFilter::best() const {
  std::pair<NodeId, double> out{-1, 0.0};
  for (const auto& [id, p] : posterior_) {
    if (id != kVirtualPlace && p > out.second) out = {id, p};
  }
  return out;
}

}  // namespace wifislam::slam::frontend::rtabmap
