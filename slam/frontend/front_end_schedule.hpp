#pragma once
// When a front end's family makes keyframes and how its back end optimises them: constants of the
// family and its options, handed to FrontEnd once (they are data, not decisions made per
// keyframe). The shared pipeline (slam/system) applies them.

#include <optional>

#include "slam/frontend/keyframe_schedule.hpp"
#include "slam/optimize/edge_pruning.hpp"
#include "slam/optimize/robust_kernel.hpp"

namespace wifislam::slam::frontend {

/// How a family's back end copes with wrong edges: a robust kernel in every optimisation and a
/// pruning schedule at the end of the run. The default is plain least squares, no pruning.
struct GraphRobustness {
  optimize::RobustKernel kernel;
  optimize::PruningSchedule pruning;
};

struct FrontEndSchedule {
  /// When the family makes keyframes by time and motion (RTAB-Map's nodes); nullopt: the
  /// pipeline's tracking-quality rule (TrackingOptions).
  std::optional<KeyframeSchedule> keyframes;
  /// The family's robust kernel and after-run pruning.
  GraphRobustness robustness;
  /// Incremental optimisation: besides after every keyframe that brought a loop closure (always),
  /// after every n-th keyframe (RGBDSLAMv2's `optimizer_skip_step`); 0: only after loop closures.
  int optimise_every_keyframes = 0;
  /// How an incremental optimisation stops: 0, after the pipeline's fixed iteration budget
  /// (PoseGraphOptions::incremental_max_iterations); > 0, in rounds until chi^2 improves by less
  /// than this fraction (RGBDSLAMv2's schedule: slam/optimize/pose_graph_optimizer.hpp).
  double optimisation_convergence = 0.0;
};

}  // namespace wifislam::slam::frontend
