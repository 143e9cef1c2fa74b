#pragma once
// Options of the RTAB-Map-style front end. Defaults are RTAB-Map's (Parameters.h), named after its
// parameters; the flat `--set` keys are listed in slam_options.cpp.
//
// Vis/MinInliers (20) is the pipeline's `min_matches` (RANSAC inliers needed to accept a visual
// transformation, default 20): candidates are verified by the shared pipeline, so the two are one
// setting.

#include <limits>
#include <string>

#include "slam/frontend/rtabmap/bayes_filter.hpp"

namespace wifislam::slam {

/// Deterministic processing time of one node, in milliseconds: a fixed part plus work units
/// (RTAB-Map measures wall-clock, which makes runs machine-dependent; DESIGN.md, "Ground truth
/// and metrics"). The units are the front end's own work counters, so a run's transfers are
/// exactly reproducible whatever the load.
///
/// Calibration (first pass; 2 shared cores under a load average of ~20, release build): the
/// small test loop at 3 fps, 417 frames, 142 nodes, `--frontend rtabmap`, threshold off. Per node
/// the run folder records the thread CPU time from selection to memory management (cpu_ms; the
/// wall-clock was 4.4 x larger under that load). A least-squares fit of cpu_ms over the 105 nodes
/// without a verification gives 0.94 ms + 1.76e-6 ms per descriptor-word comparison (rms residual
/// ~5 ms). The likelihood terms and hypotheses grow with the map like the vocabulary does, so that
/// run cannot separate them; together they are under 1 ms per node at ~130 hypotheses, and the
/// values below are estimates. Thread CPU does not see OpenCV's worker threads, so a verification
/// is charged its mean wall-clock per long-term comparison in the same run (timing.json roles:
/// 9.0 ms). The fixed part adds the node's feature extraction (timing.json: 8.5 ms per frame).
/// To be redone on an idle machine; `cost_ms_*` override every value.
struct RtabmapCostModel {
  /// Per node: its feature extraction (RTAB-Map extracts a node's features inside its
  /// processing) and the fixed part of memory update and Bayes bookkeeping (0.94 + 8.5).
  double ms_per_node = 9.4;
  /// Per descriptor-word distance of the node's quantisation (exhaustive vocabulary search).
  double ms_per_word_comparison = 1.76e-6;
  /// Per inverted-index reference visited by the tf-idf likelihood (estimate).
  double ms_per_likelihood_term = 1e-4;
  /// Per hypothesis of the Bayes filter: prediction column and update (estimate).
  double ms_per_hypothesis = 4e-3;
  /// Per visual verification (matching + RANSAC of one candidate).
  double ms_per_verification = 9.0;
};

struct RtabmapOptions {
  /// Rtabmap/DetectionRate (Hz): at most this many nodes per second (0 = no time limit) ...
  double detection_rate_hz = 1.0;
  /// ... and only after RGBD/LinearUpdate metres or RGBD/AngularUpdate radians of motion since
  /// the last node (the tracking estimate, which starts from wheel odometry).
  double linear_update_m = 0.1;
  double angular_update_rad = 0.1;
  /// Mem/STMSize: the newest nodes kept out of loop-closure search.
  int stm_size = 10;
  /// Mem/RehearsalSimilarity: a new node this similar to the previous one merges with it.
  double rehearsal_similarity = 0.6;
  /// Kp/MaxFeatures: the strongest keypoints of a node quantised into words.
  int max_features = 500;
  /// Kp/NndrRatio: a descriptor joins its nearest word when d1 <= ratio x d2, else founds one.
  double nndr_ratio = 0.8;
  /// Bayes/PredictionLC: {virtual place, margin 0, margin 1, ...}.
  std::string prediction_lc = rtabmap::kDefaultPredictionLc;
  /// Bayes/VirtualPlacePriorThr: probability that "no loop closure" stays "no loop closure".
  double virtual_place_prior = 0.9;
  /// Rtabmap/LoopThr: the best hypothesis becomes a loop-closure candidate at this posterior.
  double loop_threshold = 0.11;
  /// Rtabmap/MaxRetrieved: LTM neighbours of the best hypothesis brought back per node.
  int max_retrieved = 2;
  /// RGBD/ProximityBySpace: also look for local loop closures among WM nodes near the node's
  /// estimated position (RtabmapFrontEnd, step 6).
  bool proximity_by_space = true;
  /// RGBD/LocalRadius (m): WM nodes this close to the node's estimated position ...
  double local_radius_m = 10.0;
  /// ... and at most RGBD/ProximityMaxGraphDepth links away over STM and WM (0 = any).
  int proximity_max_graph_depth = 50;
  /// RGBD/ProximityMaxPaths: paths (runs of consecutive nodes) verified, one node each (0: all).
  int proximity_max_paths = 3;
  /// RGBD/ProximityPathFilteringRadius (m): a path's chosen node is verified only this close.
  double proximity_filtering_radius_m = 1.0;
  /// RGBD/ProximityAngle (deg): path nodes looking more than this away from the node's heading
  /// are not chosen.
  double proximity_angle_deg = 45.0;
  /// RGBD/OptimizeMaxError: a loop closure is dropped when, after a trial optimisation, some link's
  /// error exceeds this many of its own standard deviations.
  double optimize_max_error = 3.0;
  /// Rtabmap/TimeThr in ms: over it, WM nodes move to LTM. RTAB-Map's 0 (off) is infinity here.
  double time_threshold_ms = std::numeric_limits<double>::infinity();
  /// What the threshold is compared with: "cost" (the deterministic cost model) or "wall"
  /// (measured wall-clock of the node's selection, verification and memory management).
  std::string time_source = "cost";
  RtabmapCostModel cost;
  /// With a Wi-Fi module: LTM nodes of similar clusters retrieved per node (0 = all of them; they
  /// are the nodes the bounded search scores anyway, see RtabmapFrontEnd).
  int wifi_max_retrieved = 0;
};

}  // namespace wifislam::slam
