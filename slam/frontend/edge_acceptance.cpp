#include "slam/frontend/edge_acceptance.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

namespace wifislam::slam::frontend {

std::vector<std::size_t> AcceptAllHypotheses::choose(const std::vector<Hypothesis>& hypotheses,
                                                     const AcceptanceContext& /*context*/) const {
  std::vector<std::size_t> out(hypotheses.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = i;
  return out;
}

std::vector<std::size_t> AcceptBestLoopHypothesis::choose(
    const std::vector<Hypothesis>& hypotheses, const AcceptanceContext& /*context*/) const {
  std::vector<std::size_t> out;
  std::size_t best = hypotheses.size();
  for (std::size_t i = 0; i < hypotheses.size(); ++i) {
    if (hypotheses[i].edge_type != graph::EdgeType::kLoop ||
        hypotheses[i].candidate.role == CandidateRole::kProximity) {
      out.push_back(i);
    } else if (best == hypotheses.size() ||
               hypotheses[i].transformation.inliers > hypotheses[best].transformation.inliers) {
      best = i;
    }
  }
  if (best < hypotheses.size()) out.push_back(best);
  std::sort(out.begin(), out.end());
  return out;
}

std::optional<double> edge_error_ratio(const graph::PoseGraph& graph,
                                       const graph::GraphEdge& edge) {
  // RTAB-Map's links carry a diagonal covariance, so 1 / information diagonal is each axis'
  // variance there. Ours are full 6x6 matrices from the inliers' geometry, whose translation and
  // rotation are strongly coupled (a yaw and a sideways shift explain the same image motion), so
  // 1 / diagonal would understate the variance by orders of magnitude; the marginal variances are
  // the diagonal of the covariance, the inverse of the information.
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(edge.information);
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive() || !(ldlt.vectorD().minCoeff() > 0.0)) {
    return std::nullopt;
  }
  const Eigen::Matrix<double, 6, 6> covariance =
      ldlt.solve(Eigen::Matrix<double, 6, 6>::Identity());
  const double variance_t = covariance.diagonal().head<3>().maxCoeff();
  const double variance_r = covariance.diagonal().tail<3>().maxCoeff();
  if (!(variance_t > 0.0) || !(variance_r > 0.0) || variance_t > 1.0) return std::nullopt;
  const Pose estimated = graph.node(edge.from).pose.inverse() * graph.node(edge.to).pose;
  const double linear_m =
      (estimated.translation() - edge.from_to.translation()).cwiseAbs().maxCoeff();
  const double angular_rad =
      Eigen::AngleAxisd(edge.from_to.linear().transpose() * estimated.linear()).angle();
  return std::max(linear_m / std::sqrt(variance_t), angular_rad / std::sqrt(variance_r));
}

AcceptGraphConsistentHypotheses::AcceptGraphConsistentHypotheses(
    std::unique_ptr<EdgeAcceptance> inner, double max_error_ratio,
    optimize::PoseGraphOptions graph_options, int iterations)
    : inner_(std::move(inner)),
      max_error_ratio_(max_error_ratio),
      graph_options_(std::move(graph_options)),
      iterations_(iterations) {}

std::vector<std::size_t> AcceptGraphConsistentHypotheses::choose(
    const std::vector<Hypothesis>& hypotheses, const AcceptanceContext& context) const {
  std::vector<std::size_t> chosen = inner_->choose(hypotheses, context);
  const auto is_loop = [&](std::size_t i) {
    return hypotheses[i].edge_type == graph::EdgeType::kLoop;
  };
  while (std::any_of(chosen.begin(), chosen.end(), is_loop)) {
    graph::PoseGraph trial = *context.graph;
    bool have_pose = context.keyframe_has_pose;
    for (const graph::GraphEdge& e : context.other_edges) {
      trial.add_edge(e);
      if (!have_pose && e.to == context.keyframe) {
        trial.set_pose(context.keyframe, trial.node(e.from).pose * e.from_to);
        have_pose = true;
      }
    }
    const std::size_t first_new_edge = trial.edges().size();
    for (std::size_t i : chosen) {
      const Hypothesis& h = hypotheses[i];
      trial.add_edge({h.candidate.keyframe, context.keyframe, h.edge_type,
                      h.transformation.a_from_b, h.transformation.information,
                      h.transformation.inliers});
      if (!have_pose) {
        trial.set_pose(context.keyframe,
                       trial.node(h.candidate.keyframe).pose * h.transformation.a_from_b);
        have_pose = true;
      }
    }
    optimize::optimise_pose_graph(trial, graph_options_, iterations_);
    double worst_link = 0.0;
    for (const graph::GraphEdge& e : trial.edges()) {
      worst_link = std::max(worst_link, edge_error_ratio(trial, e).value_or(0.0));
    }
    if (worst_link <= max_error_ratio_) break;
    // Inconsistent: drop the new loop edge that fits worst, and try the rest.
    std::size_t worst = chosen.size();
    double worst_ratio = -1.0;
    for (std::size_t k = 0; k < chosen.size(); ++k) {
      if (!is_loop(chosen[k])) continue;
      const double ratio = edge_error_ratio(trial, trial.edges()[first_new_edge + k]).value_or(0.0);
      if (ratio > worst_ratio) {
        worst_ratio = ratio;
        worst = k;
      }
    }
    chosen.erase(chosen.begin() + static_cast<std::ptrdiff_t>(worst));
  }
  return chosen;
}

}  // namespace wifislam::slam::frontend
