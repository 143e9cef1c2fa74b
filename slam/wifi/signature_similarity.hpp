#pragma once
// Wi-Fi similarity (paper, "Wi-Fi Similarity Metric"): the cosine of the angle between two RSSI
// vectors, each AP weighted max(0, rssi_dbm - floor_dbm), an AP missing from one signature
// counting 0 there. Cosine is scale invariant, so a receiver that reads every AP a few dB lower
// (another card, another gain) still matches. A vector of zero norm (empty signature, or all
// readings at or below the floor) carries no information: its similarity to anything is 0.

#include <Eigen/Core>

#include <map>
#include <vector>

#include "slam/wifi/wifi_signature.hpp"

namespace wifislam::slam::wifi {

/// Reference form for two signatures (merge over the sorted AP lists).
double cosine_similarity(const WifiSignature& a, const WifiSignature& b, double floor_dbm);

/// Many signatures (e.g. the clusters' representatives) against one query at once: rows are the
/// stored signatures' unit-norm weight vectors over a growing AP index, so all similarities are one
/// matrix-vector product. Cost per query: O(rows x APs) multiply-adds, microseconds for hundreds
/// of clusters, against milliseconds for one visual comparison.
class SignatureSimilarityIndex {
 public:
  explicit SignatureSimilarityIndex(double floor_dbm) : floor_dbm_(floor_dbm) {}

  /// Adds a row; returns its index (0, 1, ...).
  int add(const WifiSignature& signature);
  int size() const { return rows_; }

  /// Cosine similarity of `query` with every stored row, in row order.
  Eigen::VectorXd similarities(const WifiSignature& query) const;

 private:
  int column_of(AccessPointKey ap);

  double floor_dbm_;
  std::map<AccessPointKey, int> columns_;
  Eigen::MatrixXd weights_;  // capacity-managed; the used block is rows_ x columns_.size()
  int rows_ = 0;
};

}  // namespace wifislam::slam::wifi
