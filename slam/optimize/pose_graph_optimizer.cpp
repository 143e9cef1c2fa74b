#include "slam/optimize/pose_graph_optimizer.hpp"

#include <algorithm>
#include <memory>
#include <vector>

#include <ceres/ceres.h>

#include <Eigen/Eigenvalues>

#include "core/error.hpp"
#include "slam/optimize/relative_pose_error.hpp"

namespace wifislam::slam {

Eigen::Matrix<double, 6, 6> information_square_root(const Information6& information,
                                                    double min_eigenvalue) {
  const Information6 symmetric = 0.5 * (information + information.transpose());
  Eigen::LLT<Information6> llt(symmetric);
  if (llt.info() == Eigen::Success) return llt.matrixU();
  const Eigen::SelfAdjointEigenSolver<Information6> eig(symmetric);
  const Eigen::Matrix<double, 6, 1> values = eig.eigenvalues().cwiseMax(min_eigenvalue);
  const Information6 repaired =
      eig.eigenvectors() * values.asDiagonal() * eig.eigenvectors().transpose();
  return Eigen::LLT<Information6>(0.5 * (repaired + repaired.transpose())).matrixU();
}

namespace {

ceres::LossFunction* make_loss(const PoseGraphOptions& options) {
  if (options.robust_loss == "none") return nullptr;
  if (options.robust_loss == "huber") return new ceres::HuberLoss(options.robust_loss_scale);
  if (options.robust_loss == "cauchy") return new ceres::CauchyLoss(options.robust_loss_scale);
  throw InvalidInputError("robust_loss must be none, huber or cauchy, got '" + options.robust_loss +
                          "'");
}

}  // namespace

OptimisationSummary optimise_pose_graph(PoseGraph& graph, const PoseGraphOptions& options,
                                        int max_iterations, KeyframeId fixed_node) {
  OptimisationSummary summary;
  if (graph.node_count() < 2 || graph.edges().empty()) return summary;

  struct State {
    Eigen::Vector3d p;
    Eigen::Quaterniond q;
  };
  std::vector<State> states(graph.node_count());
  for (const GraphNode& node : graph.nodes()) {
    states[static_cast<std::size_t>(node.id)] = {
        node.pose.translation(), Eigen::Quaterniond(node.pose.linear()).normalized()};
  }

  // The loss is shared by all loop edges, so the problem must not delete it per block.
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  std::unique_ptr<ceres::LossFunction> loss(make_loss(options));
  // One manifold object for all quaternions (the problem deletes it once).
  ceres::Manifold* quaternion_manifold = new ceres::EigenQuaternionManifold;
  bool manifold_used = false;
  for (std::size_t i = 0; i < states.size(); ++i) {
    // Nodes without edges have no residual: they are left out of the problem.
    if (graph.adjacent(static_cast<KeyframeId>(i)).empty()) continue;
    problem.AddParameterBlock(states[i].p.data(), 3);
    problem.AddParameterBlock(states[i].q.coeffs().data(), 4, quaternion_manifold);
    manifold_used = true;
  }
  if (!manifold_used) delete quaternion_manifold;
  for (const GraphEdge& edge : graph.edges()) {
    State& a = states[static_cast<std::size_t>(edge.from)];
    State& b = states[static_cast<std::size_t>(edge.to)];
    ceres::LossFunction* edge_loss = edge.type == EdgeType::kLoop ? loss.get() : nullptr;
    problem.AddResidualBlock(
        RelativePoseError::create(edge.from_to, information_square_root(edge.information)),
        edge_loss, a.p.data(), a.q.coeffs().data(), b.p.data(), b.q.coeffs().data());
  }
  State& fixed = states.at(static_cast<std::size_t>(fixed_node));
  if (problem.HasParameterBlock(fixed.p.data())) {
    problem.SetParameterBlockConstant(fixed.p.data());
    problem.SetParameterBlockConstant(fixed.q.coeffs().data());
  }

  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  solver_options.max_num_iterations = max_iterations;
  solver_options.num_threads = std::max(1, options.threads);
  solver_options.minimizer_progress_to_stdout = false;
  solver_options.logging_type = ceres::SILENT;
  ceres::Solver::Summary ceres_summary;
  ceres::Solve(solver_options, &problem, &ceres_summary);

  for (const GraphNode& node : graph.nodes()) {
    const State& s = states[static_cast<std::size_t>(node.id)];
    graph.set_pose(node.id, pose_from_translation_quaternion(s.p, s.q));
  }
  summary.ran = true;
  summary.iterations = static_cast<int>(ceres_summary.iterations.size());
  summary.initial_cost = ceres_summary.initial_cost;
  summary.final_cost = ceres_summary.final_cost;
  summary.seconds = ceres_summary.total_time_in_seconds;
  summary.brief = ceres_summary.BriefReport();
  return summary;
}

}  // namespace wifislam::slam
