#include "slam/graph/pose_graph.hpp"

#include <algorithm>
#include <deque>

#include "core/error.hpp"

namespace wifislam::slam::graph {

std::string to_string(EdgeType type) {
  switch (type) {
    case EdgeType::kOdometry:
      return "odometry";
    case EdgeType::kVisual:
      return "visual";
    case EdgeType::kLoop:
      return "loop";
    case EdgeType::kWeak:
      return "weak";
  }
  return "unknown";
}

KeyframeId PoseGraph::add_node(Timestamp time, std::int64_t frame_index, const Pose& pose) {
  const KeyframeId id = static_cast<KeyframeId>(nodes_.size());
  nodes_.push_back({id, time, frame_index, pose});
  adjacency_.emplace_back();
  return id;
}

void PoseGraph::add_edge(const GraphEdge& edge) {
  const auto n = static_cast<KeyframeId>(nodes_.size());
  if (edge.from < 0 || edge.to < 0 || edge.from >= n || edge.to >= n || edge.from == edge.to) {
    throw InvalidInputError("pose graph edge " + std::to_string(edge.from) + " -> " +
                            std::to_string(edge.to) + " does not join two distinct nodes");
  }
  edges_.push_back(edge);
  for (auto [a, b] : {std::pair{edge.from, edge.to}, std::pair{edge.to, edge.from}}) {
    auto& list = adjacency_[static_cast<std::size_t>(a)];
    const auto it = std::lower_bound(list.begin(), list.end(), b);
    if (it == list.end() || *it != b) list.insert(it, b);
  }
}

bool PoseGraph::has_edge(KeyframeId a, KeyframeId b) const {
  if (a < 0 || static_cast<std::size_t>(a) >= adjacency_.size()) return false;
  const auto& list = adjacency_[static_cast<std::size_t>(a)];
  return std::binary_search(list.begin(), list.end(), b);
}

std::vector<KeyframeId> PoseGraph::geodesic_neighbours(KeyframeId id, int depth) const {
  std::vector<KeyframeId> out;
  if (id < 0 || static_cast<std::size_t>(id) >= nodes_.size() || depth <= 0) return out;
  std::vector<int> distance(nodes_.size(), -1);
  distance[static_cast<std::size_t>(id)] = 0;
  std::deque<KeyframeId> queue{id};
  while (!queue.empty()) {
    const KeyframeId current = queue.front();
    queue.pop_front();
    const int d = distance[static_cast<std::size_t>(current)];
    if (d == depth) continue;
    for (KeyframeId next : adjacent(current)) {
      if (distance[static_cast<std::size_t>(next)] >= 0) continue;
      distance[static_cast<std::size_t>(next)] = d + 1;
      out.push_back(next);
      queue.push_back(next);
    }
  }
  // BFS order is already by distance; sort ids within each distance for a canonical order.
  std::stable_sort(out.begin(), out.end(), [&](KeyframeId a, KeyframeId b) {
    const int da = distance[static_cast<std::size_t>(a)];
    const int db = distance[static_cast<std::size_t>(b)];
    return da != db ? da < db : a < b;
  });
  return out;
}

}  // namespace wifislam::slam::graph
