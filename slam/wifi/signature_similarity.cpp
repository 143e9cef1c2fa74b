#include "slam/wifi/signature_similarity.hpp"

#include <algorithm>
#include <cmath>

namespace wifislam::slam::wifi {

namespace {

double weight(double rssi_dbm, double floor_dbm) { return std::max(0.0, rssi_dbm - floor_dbm); }

double norm(const WifiSignature& s, double floor_dbm) {
  double sum = 0.0;
  for (const ApStrength& a : s.strengths()) sum += std::pow(weight(a.rssi_dbm, floor_dbm), 2);
  return std::sqrt(sum);
}

}  // namespace

double cosine_similarity(const WifiSignature& a, const WifiSignature& b, double floor_dbm) {
  const double norms = norm(a, floor_dbm) * norm(b, floor_dbm);
  if (norms == 0.0) return 0.0;
  double dot = 0.0;
  auto ia = a.strengths().begin();
  auto ib = b.strengths().begin();
  while (ia != a.strengths().end() && ib != b.strengths().end()) {
    if (ia->ap < ib->ap) {
      ++ia;
    } else if (ib->ap < ia->ap) {
      ++ib;
    } else {
      dot += weight(ia->rssi_dbm, floor_dbm) * weight(ib->rssi_dbm, floor_dbm);
      ++ia;
      ++ib;
    }
  }
  return dot / norms;
}

int SignatureSimilarityIndex::column_of(AccessPointKey ap) {
  const auto [it, inserted] = columns_.emplace(ap, static_cast<int>(columns_.size()));
  if (inserted && it->second >= weights_.cols()) {
    const Eigen::Index capacity = std::max<Eigen::Index>(64, 2 * weights_.cols());
    weights_.conservativeResize(weights_.rows(), capacity);
    weights_.rightCols(capacity - it->second).setZero();
  }
  return it->second;
}

int SignatureSimilarityIndex::add(const WifiSignature& signature) {
  if (rows_ >= weights_.rows()) {
    const Eigen::Index capacity = std::max<Eigen::Index>(16, 2 * weights_.rows());
    weights_.conservativeResize(capacity, weights_.cols());
    weights_.bottomRows(capacity - rows_).setZero();
  }
  const double n = norm(signature, floor_dbm_);
  for (const ApStrength& a : signature.strengths()) {
    const int column = column_of(a.ap);
    weights_(rows_, column) = n == 0.0 ? 0.0 : weight(a.rssi_dbm, floor_dbm_) / n;
  }
  return rows_++;
}

Eigen::VectorXd SignatureSimilarityIndex::similarities(const WifiSignature& query) const {
  const double n = norm(query, floor_dbm_);
  const auto used_columns = static_cast<Eigen::Index>(columns_.size());
  Eigen::VectorXd q = Eigen::VectorXd::Zero(used_columns);
  if (n == 0.0 || rows_ == 0) return Eigen::VectorXd::Zero(rows_);
  for (const ApStrength& a : query.strengths()) {
    // An AP no stored signature has heard adds to the query's norm only.
    const auto it = columns_.find(a.ap);
    if (it != columns_.end()) q(it->second) = weight(a.rssi_dbm, floor_dbm_) / n;
  }
  return weights_.topLeftCorner(rows_, used_columns) * q;
}

}  // namespace wifislam::slam::wifi
