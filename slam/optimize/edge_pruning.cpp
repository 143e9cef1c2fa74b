#include "slam/optimize/edge_pruning.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <sstream>

#include "core/error.hpp"
#include "slam/optimize/relative_pose_error.hpp"

namespace wifislam::slam::optimize {

double edge_chi2(const graph::PoseGraph& graph, const graph::GraphEdge& edge) {
  const Pose& a = graph.node(edge.from).pose;
  const Pose& b = graph.node(edge.to).pose;
  const Eigen::Vector3d p_a = a.translation(), p_b = b.translation();
  const Eigen::Quaterniond q_a = Eigen::Quaterniond(a.linear()).normalized();
  const Eigen::Quaterniond q_b = Eigen::Quaterniond(b.linear()).normalized();
  const RelativePoseError error(edge.from_to,
                                std::sqrt(edge.weight) * information_square_root(edge.information));
  Eigen::Matrix<double, 6, 1> r;
  error(p_a.data(), q_a.coeffs().data(), p_b.data(), q_b.coeffs().data(), r.data());
  return r.squaredNorm();
}

namespace {

bool prunable(const graph::GraphEdge& edge) {
  return !edge.pruned &&
         (edge.type == graph::EdgeType::kVisual || edge.type == graph::EdgeType::kLoop);
}

/// Whether edge `skip`'s two ends stay connected through the other unpruned edges.
bool ends_connected_without(const graph::PoseGraph& graph,
                            const std::vector<std::vector<std::size_t>>& incident,
                            std::size_t skip) {
  const graph::GraphEdge& cut = graph.edges()[skip];
  std::vector<char> seen(graph.node_count(), 0);
  std::deque<graph::KeyframeId> queue{cut.from};
  seen[static_cast<std::size_t>(cut.from)] = 1;
  while (!queue.empty()) {
    const graph::KeyframeId node = queue.front();
    queue.pop_front();
    for (std::size_t e : incident[static_cast<std::size_t>(node)]) {
      const graph::GraphEdge& edge = graph.edges()[e];
      if (e == skip || edge.pruned) continue;
      const graph::KeyframeId next = edge.from == node ? edge.to : edge.from;
      if (next == cut.to) return true;
      if (seen[static_cast<std::size_t>(next)]) continue;
      seen[static_cast<std::size_t>(next)] = 1;
      queue.push_back(next);
    }
  }
  return false;
}

}  // namespace

std::vector<PruningStage> prune_inconsistent_edges(
    graph::PoseGraph& graph, const PruningSchedule& schedule,
    const std::function<OptimisationSummary(graph::PoseGraph&)>& reoptimise) {
  std::vector<std::vector<std::size_t>> incident(graph.node_count());
  for (std::size_t e = 0; e < graph.edges().size(); ++e) {
    incident[static_cast<std::size_t>(graph.edges()[e].from)].push_back(e);
    incident[static_cast<std::size_t>(graph.edges()[e].to)].push_back(e);
  }
  std::vector<PruningStage> stages;
  for (double threshold : schedule.chi2_thresholds) {
    PruningStage stage;
    stage.threshold_chi2 = threshold;
    // Worst first, so that of two edges that could each be removed but not both, the worse one
    // goes and the better one is discounted.
    std::vector<std::pair<double, std::size_t>> over;
    for (std::size_t e = 0; e < graph.edges().size(); ++e) {
      const graph::GraphEdge& edge = graph.edges()[e];
      if (!prunable(edge) || edge.weight < 1.0) continue;  // discounted: already out of play
      const double chi2 = edge_chi2(graph, edge);
      if (!(chi2 <= threshold)) over.emplace_back(chi2, e);  // NaN counts as over
    }
    std::sort(over.begin(), over.end(), [](const auto& x, const auto& y) {
      return x.first != y.first ? x.first > y.first : x.second < y.second;
    });
    for (const auto& [chi2, e] : over) {
      if (ends_connected_without(graph, incident, e)) {
        graph.prune_edge(e);
        ++stage.pruned;
      } else {
        graph.set_edge_weight(e, schedule.discount_weight);
        ++stage.discounted;
      }
    }
    if (stage.pruned + stage.discounted > 0) stage.optimisation = reoptimise(graph);
    stages.push_back(stage);
  }
  return stages;
}

}  // namespace wifislam::slam::optimize
