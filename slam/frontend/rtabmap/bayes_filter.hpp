#pragma once
// RTAB-Map's discrete Bayes filter over loop-closure hypotheses (Labbé & Michaud 2013, section
// III-E; BayesFilter::computePosterior and generatePrediction). The hypotheses are the virtual
// place ("no loop closure", id kVirtualPlace) and every scored WM node.
//
//   prior      = prediction x last posterior
//   posterior  = likelihood .* prior, normalised to sum 1
//
// The prediction (transition) model, column by column:
//   from the virtual place: stay with Bayes/VirtualPlacePriorThr (0.9), the rest spread evenly
//     over the nodes;
//   from node i: Bayes/PredictionLC = {virtual, margin 0 (i itself), margin 1, ...}: the virtual
//     place gets value[0]; every hypothesis within graph margin m of i gets value[m + 1] (the
//     neighbourhood, STM excluded, comes from the caller); what the model gives to neighbours that
//     are not hypotheses goes to i itself; values below a total of 1 are spread over the other
//     hypotheses; the node part is then scaled to sum 1 - value[0].
// A hypothesis that was not in the last posterior starts at 0 (1 for all on the first update).
// The prediction is applied column by column (sparse): the work is the neighbourhood size, not
// the square of the hypothesis count.

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "slam/frontend/rtabmap/visual_vocabulary.hpp"

namespace wifislam::slam::frontend::rtabmap {

inline constexpr NodeId kVirtualPlace = -1;

/// Bayes/PredictionLC's default (RTAB-Map Parameters.h).
inline constexpr const char* kDefaultPredictionLc =
    "0.1 0.36 0.30 0.16 0.062 0.0151 0.00255 0.000324 2.5e-05 1.3e-06 4.8e-08 1.5e-09 4.5e-11";

/// Parses a space-separated prediction model (at least two values, each >= 0); throws
/// InvalidInputError naming `key`.
std::vector<double> parse_prediction_lc(const std::string& key, const std::string& text);

/// Graph neighbours of a hypothesis within `max_margin` links, with their margin (the node itself
/// at 0), restricted to what the prediction may name (RTAB-Map leaves STM out).
using NeighbourFunction = std::function<std::map<NodeId, int>(NodeId node, int max_margin)>;

class BayesFilter {
 public:
  BayesFilter(std::vector<double> prediction_lc, double virtual_place_prior);

  /// One update. `likelihood`: the normalised likelihood of every hypothesis (nodes ascending);
  /// `virtual_likelihood` that of the virtual place.
  void update(const std::map<NodeId, double>& likelihood, double virtual_likelihood,
              const NeighbourFunction& neighbours);

  /// Posterior of the last update: the virtual place and every hypothesis; sums to 1.
  const std::map<NodeId, double>& posterior() const { return posterior_; }
  double virtual_probability() const;
  /// The most probable node hypothesis (not the virtual place), ties to the lower id; {-1, 0}
  /// when there is none.
  std::pair<NodeId, double> best() const;
  /// Graph margin the prediction reaches (value count - 2).
  int max_margin() const { return static_cast<int>(prediction_lc_.size()) - 2; }

 private:
  std::vector<double> prediction_lc_;
  double total_;  // sum of prediction_lc_
  double virtual_place_prior_;
  std::map<NodeId, double> posterior_;  // includes kVirtualPlace
};

}  // namespace wifislam::slam::frontend::rtabmap
