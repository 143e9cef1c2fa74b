#pragma once
// Options of the RTAB-Map-style front end. Defaults are RTAB-Map's (Parameters.h), named after its
// parameters; the flat `--set` keys are listed in slam_options.cpp.
//
// Vis/MinInliers (20) is the pipeline's `min_matches` (RANSAC inliers needed to accept a visual
// transformation, default 20): candidates are verified by the shared pipeline, so the two are one
// setting.

#include <limits>
#include <string>

#include "core/option_table.hpp"
#include "slam/frontend/rtabmap/bayes_filter.hpp"

namespace wifislam::slam::frontend::rtabmap {

/// What Rtabmap/TimeThr is compared with: the deterministic cost model, or measured wall-clock.
enum class RtabmapTimeSource { kCost, kWall };

/// Each source with its name ("cost", "wall"), for `--set time_source=` and run.json.
inline const options::Choices<RtabmapTimeSource>& rtabmap_time_sources() {
  static const options::Choices<RtabmapTimeSource> sources = {{RtabmapTimeSource::kCost, "cost"},
                                                              {RtabmapTimeSource::kWall, "wall"}};
  return sources;
}

inline std::string to_string(RtabmapTimeSource source) {
  for (const auto& [value, name] : rtabmap_time_sources()) {
    if (value == source) return std::string(name);
  }
  return "cost";
}

/// Deterministic processing time of one node, in milliseconds: a fixed part plus work units
/// (RTAB-Map measures wall-clock, which makes runs machine-dependent; docs/evaluation.md). The
/// units are the front end's own work counters, so a run's transfers are exactly reproducible
/// whatever the load.
///
/// Calibration (2026-12-02; release build, 2 cores, otherwise idle; bench/slam/
/// rtabmap_cost_calibration.py): vanilla and Wi-Fi runs on the c_hall and b_hall twins at 3 fps,
/// threshold off, one at a time: 1 694 nodes, maps up to 443 WM nodes and ~10^5 words. Each term
/// is fitted against the thread CPU time of its own phase, which rtabmap_memory.csv records per
/// node (RTAB-Map's timing categories), so the terms do not share one collinear fit:
///   memory update  1.87e-6 ms per descriptor-word comparison (rms residual 2.7 ms; intercept
///                  -1.6 ms, taken as 0);
///   likelihood     1.67e-4 ms per inverted-index reference + 5.2e-4 ms per scored node (rms
///                  0.05 ms);
///   posterior      1.1e-2 ms per hypothesis (rms 0.25 ms);
///   verification   1.69 ms wall-clock each (mean over the 685 verifications of the nodes' roles;
///                  OpenCV's matching threads are invisible to thread CPU time);
///   per node       3.64 ms: the mean feature extraction of a frame (timing.json), which RTAB-Map
///                  does inside a node's processing.
/// Over each run the model's total is 1.01-1.04 of the measured phases + verifications +
/// extraction, and its loop-closure share (likelihood, posterior, loop hypothesis verification)
/// 0.98-1.12 of the measured one. Not charged: retrieval and transfer bookkeeping, proximity
/// selection and the graph-consistency check's trial optimisation (RGBD/OptimizeMaxError), which
/// took 2.3-3.3 s of c_hall's 23-25 s of node wall-clock. Frame-to-frame tracking is odometry,
/// outside Rtabmap/TimeThr as in RTAB-Map. `cost_ms_*` override every value.
struct RtabmapCostModel {
  /// Per node: its feature extraction (RTAB-Map extracts a node's features inside its
  /// processing); the memory update's fixed part fitted below zero.
  double ms_per_node = 3.64;
  /// Per descriptor-word distance of the node's quantisation (exhaustive vocabulary search).
  double ms_per_word_comparison = 1.87e-6;
  /// Per inverted-index reference visited by the tf-idf likelihood.
  double ms_per_likelihood_term = 1.67e-4;
  /// Per node scored by the likelihood: its score, normalisation and hypothesis bookkeeping.
  double ms_per_scored_node = 5.2e-4;
  /// Per hypothesis of the Bayes filter: prediction column and update.
  double ms_per_hypothesis = 1.1e-2;
  /// Per visual verification (matching + RANSAC of one candidate).
  double ms_per_verification = 1.69;
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
  RtabmapTimeSource time_source = RtabmapTimeSource::kCost;
  RtabmapCostModel cost;
  /// With a Wi-Fi module: LTM nodes of similar clusters retrieved per node (0 = all of them; they
  /// are the nodes the bounded search scores anyway, see RtabmapFrontEnd).
  int wifi_max_retrieved = 0;
  /// With a Wi-Fi module: WM nodes immune to transfer per node, from the most similar cluster
  /// down (0 = every node of a similar cluster, the paper's rule; a cap bounds WM where Wi-Fi
  /// cannot separate places, see RtabmapFrontEnd).
  int wifi_max_immune = 0;
};

}  // namespace wifislam::slam::frontend::rtabmap
