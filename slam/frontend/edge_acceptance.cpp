#include "slam/frontend/edge_acceptance.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace wifislam::slam {

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
    if (hypotheses[i].edge_type != EdgeType::kLoop) {
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

double edge_error_ratio(const PoseGraph& graph, const GraphEdge& edge) {
  const Pose& a = graph.node(edge.from).pose;
  const Pose& b = graph.node(edge.to).pose;
  const Pose estimated = a.inverse() * b;
  // The optimiser's residual convention (optimize/relative_pose_error.hpp), unwhitened.
  const Eigen::Vector3d translation_error = estimated.translation() - edge.from_to.translation();
  const Eigen::Quaterniond q_measured(edge.from_to.linear());
  const Eigen::Quaterniond q_estimated(estimated.linear());
  const Eigen::Vector3d rotation_error = 2.0 * (q_measured * q_estimated.conjugate()).vec();
  // Regularised inverse: an information matrix may be rank deficient along unobserved axes.
  const Information6 regularised = edge.information + 1e-9 * Information6::Identity();
  const Eigen::Matrix<double, 6, 6> covariance = regularised.inverse();
  const double variance_t = covariance.diagonal().head<3>().maxCoeff();
  const double variance_r = covariance.diagonal().tail<3>().maxCoeff();
  const double ratio_t = translation_error.norm() / std::sqrt(std::max(variance_t, 1e-18));
  const double ratio_r = rotation_error.norm() / std::sqrt(std::max(variance_r, 1e-18));
  return std::max(ratio_t, ratio_r);
}

AcceptGraphConsistentHypotheses::AcceptGraphConsistentHypotheses(
    std::unique_ptr<EdgeAcceptance> inner, double max_error_ratio, PoseGraphOptions graph_options,
    int iterations)
    : inner_(std::move(inner)),
      max_error_ratio_(max_error_ratio),
      graph_options_(std::move(graph_options)),
      iterations_(iterations) {}

std::vector<std::size_t> AcceptGraphConsistentHypotheses::choose(
    const std::vector<Hypothesis>& hypotheses, const AcceptanceContext& context) const {
  std::vector<std::size_t> chosen = inner_->choose(hypotheses, context);
  const auto is_loop = [&](std::size_t i) { return hypotheses[i].edge_type == EdgeType::kLoop; };
  while (std::any_of(chosen.begin(), chosen.end(), is_loop)) {
    PoseGraph trial = *context.graph;
    bool have_pose = context.keyframe_has_pose;
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
    optimise_pose_graph(trial, graph_options_, iterations_);
    // The worst loop edge of this keyframe, if any is out of bounds.
    std::size_t worst = chosen.size();
    double worst_ratio = max_error_ratio_;
    const std::size_t first_new_edge = trial.edges().size() - chosen.size();
    for (std::size_t k = 0; k < chosen.size(); ++k) {
      if (!is_loop(chosen[k])) continue;
      const double ratio = edge_error_ratio(trial, trial.edges()[first_new_edge + k]);
      if (ratio > worst_ratio) {
        worst_ratio = ratio;
        worst = k;
      }
    }
    if (worst == chosen.size()) break;
    chosen.erase(chosen.begin() + static_cast<std::ptrdiff_t>(worst));
  }
  return chosen;
}

}  // namespace wifislam::slam
