#include "slam/optimize/pose_graph_optimizer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include <ceres/ceres.h>

#include <Eigen/Eigenvalues>

#include "core/error.hpp"
#include "slam/optimize/relative_pose_error.hpp"

namespace wifislam::slam::optimize {

Eigen::Matrix<double, 6, 6> information_square_root(const graph::Information6& information,
                                                    double min_eigenvalue) {
  const graph::Information6 symmetric = 0.5 * (information + information.transpose());
  Eigen::LLT<graph::Information6> llt(symmetric);
  if (llt.info() == Eigen::Success) return llt.matrixU();
  const Eigen::SelfAdjointEigenSolver<graph::Information6> eig(symmetric);
  const Eigen::Matrix<double, 6, 1> values = eig.eigenvalues().cwiseMax(min_eigenvalue);
  const graph::Information6 repaired =
      eig.eigenvectors() * values.asDiagonal() * eig.eigenvectors().transpose();
  return Eigen::LLT<graph::Information6>(0.5 * (repaired + repaired.transpose())).matrixU();
}

namespace {

// Ceres' losses act on s = r^T Omega r (chi^2) with a parameter a such that rho(s) = s up to
// s = a^2 (Huber), so a = sqrt(width_chi2).
ceres::LossFunction* make_loss(const RobustKernel& kernel) {
  const double a = std::sqrt(kernel.width_chi2);
  switch (kernel.kind) {
    case RobustKernel::Kind::kNone:
      return nullptr;
    case RobustKernel::Kind::kHuber:
      return new ceres::HuberLoss(a);
    case RobustKernel::Kind::kCauchy:
      return new ceres::CauchyLoss(a);
  }
  return nullptr;
}

}  // namespace

OptimisationSummary optimise_pose_graph(graph::PoseGraph& graph, const PoseGraphOptions& options,
                                        int max_iterations, const RobustKernel& kernel,
                                        graph::KeyframeId fixed_node, double convergence) {
  OptimisationSummary summary;
  if (!(kernel.width_chi2 > 0.0) || !std::isfinite(kernel.width_chi2)) {
    throw InvalidInputError("robust kernel width must be a positive chi^2");
  }
  // Nodes with no edge left (pruned ones do not count) have no residual: they stay out.
  std::vector<char> in_problem(graph.node_count(), 0);
  bool any_edge = false;
  for (const graph::GraphEdge& edge : graph.edges()) {
    if (edge.pruned) continue;
    in_problem[static_cast<std::size_t>(edge.from)] = 1;
    in_problem[static_cast<std::size_t>(edge.to)] = 1;
    any_edge = true;
  }
  if (graph.node_count() < 2 || !any_edge) return summary;

  struct State {
    Eigen::Vector3d p;
    Eigen::Quaterniond q;
  };
  std::vector<State> states(graph.node_count());
  for (const graph::GraphNode& node : graph.nodes()) {
    states[static_cast<std::size_t>(node.id)] = {
        node.pose.translation(), Eigen::Quaterniond(node.pose.linear()).normalized()};
  }

  // The loss is shared by the edges it applies to, so the problem must not delete it per block.
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  std::unique_ptr<ceres::LossFunction> loss(make_loss(kernel));
  // One manifold object for all quaternions (the problem deletes it once).
  ceres::Manifold* quaternion_manifold = new ceres::EigenQuaternionManifold;
  bool manifold_used = false;
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (!in_problem[i]) continue;
    problem.AddParameterBlock(states[i].p.data(), 3);
    problem.AddParameterBlock(states[i].q.coeffs().data(), 4, quaternion_manifold);
    manifold_used = true;
  }
  if (!manifold_used) delete quaternion_manifold;
  std::vector<ceres::ResidualBlockId> residuals;
  for (const graph::GraphEdge& edge : graph.edges()) {
    if (edge.pruned) continue;
    State& a = states[static_cast<std::size_t>(edge.from)];
    State& b = states[static_cast<std::size_t>(edge.to)];
    ceres::LossFunction* edge_loss =
        kernel.every_edge || edge.type == graph::EdgeType::kLoop ? loss.get() : nullptr;
    residuals.push_back(problem.AddResidualBlock(
        RelativePoseError::create(
            edge.from_to, std::sqrt(edge.weight) * information_square_root(edge.information)),
        edge_loss, a.p.data(), a.q.coeffs().data(), b.p.data(), b.q.coeffs().data()));
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
  int iterations = 0;
  double initial_cost = 0.0, seconds = 0.0;
  if (convergence <= 0.0) {
    ceres::Solve(solver_options, &problem, &ceres_summary);
    iterations = static_cast<int>(ceres_summary.iterations.size());
    initial_cost = ceres_summary.initial_cost;
    seconds = ceres_summary.total_time_in_seconds;
  } else {
    // chi^2 without the kernel: what g2o's OptimizableGraph::chi2() sums (Ceres' cost is half).
    const auto raw_chi2 = [&] {
      double chi2 = 0.0;
      for (const ceres::ResidualBlockId id : residuals) {
        double cost = 0.0;
        problem.EvaluateResidualBlock(id, /*apply_loss_function=*/false, &cost, nullptr, nullptr);
        chi2 += 2.0 * cost;
      }
      return chi2;
    };
    double chi2 = std::numeric_limits<double>::infinity(), previous = chi2;
    bool first = true;
    do {
      previous = chi2;
      solver_options.max_num_iterations =
          std::min(kConvergenceRoundIterations, max_iterations - iterations);
      ceres::Solve(solver_options, &problem, &ceres_summary);
      if (first) initial_cost = ceres_summary.initial_cost;
      first = false;
      iterations += static_cast<int>(ceres_summary.iterations.size());
      seconds += ceres_summary.total_time_in_seconds;
      if (!ceres_summary.IsSolutionUsable()) break;
      chi2 = raw_chi2();
    } while (chi2 < (1.0 - convergence) * previous && iterations < max_iterations);
  }
  summary.ran = true;
  summary.usable = ceres_summary.IsSolutionUsable();
  summary.termination =
      std::string(ceres::TerminationTypeToString(ceres_summary.termination_type)) + ": " +
      ceres_summary.message;
  if (summary.usable) {
    for (const graph::GraphNode& node : graph.nodes()) {
      const State& s = states[static_cast<std::size_t>(node.id)];
      if (!s.p.allFinite() || !s.q.coeffs().allFinite()) {
        summary.usable = false;  // defensive: never write a non-finite pose
        summary.termination += " (non-finite pose)";
        break;
      }
    }
  }
  if (summary.usable) {
    for (const graph::GraphNode& node : graph.nodes()) {
      const State& s = states[static_cast<std::size_t>(node.id)];
      graph.set_pose(node.id, pose_from_translation_quaternion(s.p, s.q));
    }
  }
  summary.iterations = iterations;
  summary.initial_cost = initial_cost;
  summary.final_cost = ceres_summary.final_cost;
  summary.seconds = seconds;
  summary.brief = ceres_summary.BriefReport();
  return summary;
}

}  // namespace wifislam::slam::optimize
