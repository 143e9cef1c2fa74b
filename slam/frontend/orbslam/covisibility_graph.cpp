#include "slam/frontend/orbslam/covisibility_graph.hpp"

#include <algorithm>

namespace wifislam::slam::frontend::orbslam {

void CovisibilityGraph::add(graph::KeyframeId a, graph::KeyframeId b, int inliers) {
  if (a == b || inliers < min_weight_) return;
  int& ab = weights_[a][b];
  if (ab == 0) ++edges_;
  ab = std::max(ab, inliers);
  int& ba = weights_[b][a];
  ba = std::max(ba, inliers);
}

int CovisibilityGraph::weight(graph::KeyframeId a, graph::KeyframeId b) const {
  const auto it = weights_.find(a);
  if (it == weights_.end()) return 0;
  const auto jt = it->second.find(b);
  return jt == it->second.end() ? 0 : jt->second;
}

std::vector<graph::KeyframeId> CovisibilityGraph::connected(graph::KeyframeId k) const {
  std::vector<graph::KeyframeId> out;
  const auto it = weights_.find(k);
  if (it == weights_.end()) return out;
  for (const auto& [other, w] : it->second) out.push_back(other);
  return out;
}

std::vector<graph::KeyframeId> CovisibilityGraph::best(graph::KeyframeId k, int n) const {
  const auto it = weights_.find(k);
  if (it == weights_.end()) return {};
  std::vector<std::pair<graph::KeyframeId, int>> ranked(it->second.begin(), it->second.end());
  std::sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) {
    if (a.second != b.second) return a.second > b.second;
    return a.first > b.first;
  });
  std::vector<graph::KeyframeId> out;
  for (const auto& [other, w] : ranked) {
    if (n >= 0 && static_cast<int>(out.size()) >= n) break;
    out.push_back(other);
  }
  return out;
}

}  // namespace wifislam::slam::frontend::orbslam
