#pragma once
// The paper's Fig. 2 measurement on a simulated route: Wi-Fi signatures at pauses along the
// route (several scans per pause, BSSIDs aggregated per AP by clearing the last nibble, RSSI
// averaged), cosine similarity on max(0, rssi + 100), and the Spearman rank correlation between
// pause distance and signature similarity over all pause pairs.

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <vector>

#include "radio_model/wifi_scanner.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::test {

struct Pause {
  Eigen::Vector2d position_m;
  std::map<std::uint64_t, double> signature;  // AP (base MAC) -> mean RSSI
};

inline std::vector<Pause> pauses_along_route(const sim::world::RoutePath& route,
                                             const radio_model::WifiScanner& scanner,
                                             double spacing_m, int scans_per_pause,
                                             double receiver_height_m) {
  std::vector<Pause> pauses;
  std::size_t i = 0;
  for (double s = 0.0; s <= route.length_m(); s += spacing_m) {
    while (i + 1 < route.points_m.size() && route.arc_length_m[i + 1] < s) ++i;
    Pause pause;
    pause.position_m = route.points_m[i];
    const Eigen::Vector3d p(pause.position_m.x(), pause.position_m.y(), receiver_height_m);
    std::map<std::uint64_t, std::pair<double, int>> sums;
    for (int k = 0; k < scans_per_pause; ++k) {
      const auto t = Timestamp::from_seconds(1000.0 * static_cast<double>(pauses.size()) + 2.0 * k);
      for (const WifiReading& r : scanner.scan(t, p).readings) {
        auto& [sum, n] = sums[r.bssid.without_last_nibble().value];
        sum += r.rssi_dbm;
        ++n;
      }
    }
    for (const auto& [ap, sn] : sums) pause.signature[ap] = sn.first / sn.second;
    pauses.push_back(std::move(pause));
  }
  return pauses;
}

inline double cosine_similarity(const std::map<std::uint64_t, double>& a,
                                const std::map<std::uint64_t, double>& b) {
  auto weight = [](double rssi) { return std::max(0.0, rssi + 100.0); };
  double dot = 0, na = 0, nb = 0;
  for (const auto& [ap, v] : a) {
    na += weight(v) * weight(v);
    if (auto it = b.find(ap); it != b.end()) dot += weight(v) * weight(it->second);
  }
  for (const auto& [ap, v] : b) nb += weight(v) * weight(v);
  return na > 0 && nb > 0 ? dot / std::sqrt(na * nb) : 0.0;
}

// Ranks with ties averaged (Spearman's rho is Pearson's r of the ranks).
inline std::vector<double> ranks(const std::vector<double>& v) {
  std::vector<std::size_t> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
  std::vector<double> r(v.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]]) ++j;
    for (std::size_t k = i; k <= j; ++k) r[order[k]] = 0.5 * static_cast<double>(i + j) + 1.0;
    i = j + 1;
  }
  return r;
}

inline double spearman(const std::vector<double>& x, const std::vector<double>& y) {
  const auto rx = ranks(x), ry = ranks(y);
  const double n = static_cast<double>(rx.size());
  const double mx = std::accumulate(rx.begin(), rx.end(), 0.0) / n;
  const double my = std::accumulate(ry.begin(), ry.end(), 0.0) / n;
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < rx.size(); ++i) {
    sxy += (rx[i] - mx) * (ry[i] - my);
    sxx += (rx[i] - mx) * (rx[i] - mx);
    syy += (ry[i] - my) * (ry[i] - my);
  }
  return sxy / std::sqrt(sxx * syy);
}

/// Spearman's rho between pause distance and signature similarity over all pause pairs.
inline double distance_similarity_spearman(const std::vector<Pause>& pauses) {
  std::vector<double> dist, sim;
  for (std::size_t i = 0; i < pauses.size(); ++i) {
    for (std::size_t j = i + 1; j < pauses.size(); ++j) {
      dist.push_back((pauses[i].position_m - pauses[j].position_m).norm());
      sim.push_back(cosine_similarity(pauses[i].signature, pauses[j].signature));
    }
  }
  return spearman(dist, sim);
}

}  // namespace wifislam::test
