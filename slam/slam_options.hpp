#pragma once
// Everything a SLAM run can be told (Ceres style: every field carries its default and says what it
// trades off). The CLI's `--set key=value`, study files' `slam.*` axes and run.json use the flat
// keys of visit_options(), which are the paper's and RGBDSLAMv2's parameter names where those
// exist.

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/option_table.hpp"
#include "slam/feature/orb_feature_extractor.hpp"
#include "slam/frontend/orbslam/orbslam_options.hpp"
#include "slam/frontend/rgbdslam/rgbdslam_options.hpp"
#include "slam/frontend/rtabmap/rtabmap_options.hpp"
#include "slam/optimize/pose_graph_optimizer.hpp"
#include "slam/solve/visual_transformation.hpp"
#include "slam/wifi/wifi_options.hpp"

namespace wifislam::slam {

struct TrackingOptions {
  /// A frame becomes a keyframe when its inliers against the last keyframe drop below this
  /// (never below `min_matches`). Higher: denser keyframes, more comparisons, less drift.
  int keyframe_min_inliers = 80;
  /// ... or when it has moved this far from the last keyframe. Smaller bounds: denser keyframes.
  double keyframe_max_translation_m = 0.4;
  double keyframe_max_rotation_rad = 0.35;
  /// Accepted comparisons with keyframes at least this many keyframes back are loop closures
  /// (edge type "loop", optimisation triggered); nearer ones are ordinary visual edges.
  int loop_min_keyframe_gap = 15;
  /// ... and that lie at least this far back along the estimated path (tracking estimate at
  /// keyframe creation). Nearer matches are ordinary visual edges. 10 m = the evaluation's
  /// `revisit_min_path_m`, so "loop closure" means the same on both sides.
  double loop_min_path_m = 10.0;
  /// When tracking is lost, also try this many recent keyframes (relocalisation).
  int relocalisation_keyframes = 5;
  /// Add a wheel-odometry edge between consecutive keyframes whenever odometry is available.
  /// RGBD SLAM uses no odometry (off); odometry still bridges tracking loss either way.
  bool odometry_edges = false;
  /// Standard deviations of an odometry edge (per edge, not per metre).
  double odometry_sigma_m = 0.05;
  double odometry_sigma_rad = 0.02;
  /// Standard deviations of a weak edge (tracking lost, no odometry): "somewhere near here".
  double weak_sigma_m = 2.0;
  double weak_sigma_rad = 1.0;
};

struct SlamOptions {
  /// SLAM front end (memory, candidate selection, acceptance), see
  /// slam/frontend/front_end_registry.hpp.
  std::string frontend = "rgbdslam";
  /// The Wi-Fi module, held by whichever front end runs (off = the vanilla front end).
  wifi::WifiOptions wifi;
  /// Seed of every random draw of the run (e.g. RGBD-SLAM's random keyframes).
  std::uint64_t seed = 1;
  feature::FeatureOptions features;
  solve::VisualTransformOptions transform;
  TrackingOptions tracking;
  frontend::rgbdslam::RgbdslamOptions rgbdslam;
  frontend::rtabmap::RtabmapOptions rtabmap;
  frontend::orbslam::OrbslamOptions orbslam;
  optimize::PoseGraphOptions graph;
};

/// Every settable option of `o` (core/option_table.hpp): its flat key (the paper's, RGBDSLAMv2's,
/// RTAB-Map's or ORB-SLAM2's parameter name where there is one), where it lives, and what it means.
/// A data table: one line per option.
template <class V>
void visit_options(V& v, SlamOptions& o) {
  v.text("frontend", o.frontend, "SLAM front end (memory, candidates, acceptance)");
  v.uint64("seed", o.seed, "seed of every random draw");
  v.boolean("wifi", o.wifi.enabled, "Wi-Fi module held by the front end (clustering, bounding)");
  v.number("wifi_similarity", o.wifi.similarity,
           "cosine similarity at or above which signatures are similar");
  v.number("wifi_floor_dbm", o.wifi.floor_dbm, "RSSI floor: weight = max(0, rssi - floor) (dBm)");
  v.number("wifi_pause_gap_s", o.wifi.pause_gap_s, "scan gap that ends a pause (s)");
  v.number("wifi_pause_motion_m", o.wifi.pause_motion_m, "odometry motion that ends a pause (m)");
  v.integer("max_keypoints", o.features.max_keypoints, "ORB keypoints per frame");
  v.number("orb_scale_factor", o.features.scale_factor, "ORB pyramid scale step");
  v.integer("orb_levels", o.features.pyramid_levels, "ORB pyramid levels");
  v.integer("fast_threshold", o.features.fast_threshold, "FAST corner threshold");
  v.number("min_depth_m", o.features.min_depth_m, "nearest usable depth reading (m)");
  v.number("max_depth_m", o.features.max_depth_m, "farthest usable depth reading (m)");
  v.number("match_ratio", o.transform.matching.ratio, "Lowe ratio test threshold");
  v.integer("max_hamming_distance", o.transform.matching.max_hamming_distance,
            "largest accepted descriptor distance");
  v.integer("min_matches", o.transform.min_matches,
            "minimum RANSAC inliers to accept a transformation (the paper's min_matches: agreeing "
            "features; RGBDSLAMv2 also gates on raw matches, see visual_transformation.hpp)");
  v.number("inlier_distance", o.transform.inlier_distance,
           "RANSAC inlier threshold: reprojection error (px)");
  v.integer("ransac_iterations", o.transform.ransac_iterations, "maximum RANSAC iterations");
  v.number("ransac_confidence", o.transform.ransac_confidence, "RANSAC stopping confidence (< 1)");
  v.number("min_reprojection_sigma_px", o.transform.min_reprojection_sigma_px,
           "floor of the reprojection noise in the information matrix (px)");
  v.number(
      "information_scale", o.transform.information_scale,
      "multiplies visual edges' information so correct edges' chi^2 follows chi^2(6) (measured)");
  v.number("depth_noise_coeff_per_m", o.transform.depth_noise_coeff_per_m,
           "depth noise sigma_z = coeff z^2 in the information matrix (1/m)");
  v.number("depth_consistency_sigmas", o.transform.depth_consistency_sigmas,
           "depth agreement required of inliers with depth in both frames (sigmas; 0 = off)");
  v.integer("keyframe_min_inliers", o.tracking.keyframe_min_inliers,
            "new keyframe when tracking inliers drop below");
  v.number("keyframe_max_translation_m", o.tracking.keyframe_max_translation_m,
           "new keyframe after this much translation (m)");
  v.number("keyframe_max_rotation_rad", o.tracking.keyframe_max_rotation_rad,
           "new keyframe after this much rotation (rad)");
  v.integer("loop_min_keyframe_gap", o.tracking.loop_min_keyframe_gap,
            "keyframes back from which an accepted comparison is a loop closure");
  v.number("loop_min_path_m", o.tracking.loop_min_path_m,
           "estimated path length back from which an accepted comparison is a loop closure (m)");
  v.integer("relocalisation_keyframes", o.tracking.relocalisation_keyframes,
            "recent keyframes tried when tracking is lost");
  v.boolean("odometry_edges", o.tracking.odometry_edges,
            "odometry edges between consecutive keyframes");
  v.number("odometry_sigma_m", o.tracking.odometry_sigma_m, "odometry edge translation sigma (m)");
  v.number("odometry_sigma_rad", o.tracking.odometry_sigma_rad,
           "odometry edge rotation sigma (rad)");
  v.number("weak_sigma_m", o.tracking.weak_sigma_m, "weak edge translation sigma (m)");
  v.number("weak_sigma_rad", o.tracking.weak_sigma_rad, "weak edge rotation sigma (rad)");
  v.integer("predecessor_candidates", o.rgbdslam.predecessor_candidates,
            "rgbdslam: recent keyframes compared (RGBDSLAMv2: 4; before 2015: 2)");
  v.integer("neighbor_candidates", o.rgbdslam.neighbor_candidates,
            "rgbdslam: geodesic neighbours sampled, weighted by id distance (4; before 2015: 2)");
  v.integer("geodesic_depth", o.rgbdslam.geodesic_depth, "rgbdslam: graph depth of neighbours");
  v.integer("min_sampled_candidates", o.rgbdslam.min_sampled_candidates,
            "rgbdslam: long-term candidates, random earlier keyframes (4; before 2015: 2)");
  v.integer("wifi_long_term_candidates", o.rgbdslam.wifi_long_term_candidates,
            "rgbdslam with Wi-Fi: long-term candidates from similar clusters, best signature first "
            "(-1 = min_sampled_candidates, 0 = all)");
  v.choice("robust_kernel", o.rgbdslam.robust_kernel, optimize::robust_kernel_kinds(),
           "rgbdslam: kernel on every edge: none, huber (RGBDSLAMv2), cauchy");
  v.number("robust_kernel_chi2", o.rgbdslam.robust_kernel_chi2,
           "rgbdslam: chi^2 where the kernel leaves the quadratic (4 x the last pruning stage)");
  v.integer("optimizer_skip_step", o.rgbdslam.optimizer_skip_step,
            "rgbdslam: optimise the graph after every n-th keyframe too, not only after loop "
            "closures (RGBDSLAMv2: 1; 0 = after loop closures only)");
  v.number(
      "optimizer_convergence", o.rgbdslam.optimizer_convergence,
      "rgbdslam: each incremental optimisation runs rounds of 5 iterations until chi^2 improves "
      "by less than this fraction (RGBDSLAMv2's optimizer_iterations 0.01; capped at "
      "optimizer_iterations); 0 = at most optimizer_incremental_iterations");
  v.number_list(
      "prune_chi2", o.rgbdslam.prune_chi2,
      "rgbdslam: after-run pruning stages, chi^2 thresholds (RGBDSLAMv2's 5,1,0.25 rescaled to "
      "calibrated information: last = chi^2(6) 99.9 %); none = keep every edge");
  v.number("detection_rate_hz", o.rtabmap.detection_rate_hz,
           "rtabmap: Rtabmap/DetectionRate, most nodes per second; 0 = no time limit (1)");
  v.number("linear_update_m", o.rtabmap.linear_update_m,
           "rtabmap: RGBD/LinearUpdate, least translation since the last node for a new one (0.1)");
  v.number("angular_update_rad", o.rtabmap.angular_update_rad,
           "rtabmap: RGBD/AngularUpdate, least rotation since the last node for a new one (0.1)");
  v.integer("stm_size", o.rtabmap.stm_size,
            "rtabmap: Mem/STMSize, newest nodes never searched for loop closures, >= 1 (10)");
  v.number("rehearsal_similarity", o.rtabmap.rehearsal_similarity,
           "rtabmap: Mem/RehearsalSimilarity, similarity with the previous node that merges (0.6)");
  v.integer("kp_max_features", o.rtabmap.max_features,
            "rtabmap: Kp/MaxFeatures, strongest keypoints per node quantised into words (500)");
  v.number("kp_nndr_ratio", o.rtabmap.nndr_ratio,
           "rtabmap: Kp/NndrRatio, nearest-word distance ratio, else a new word (0.8)");
  v.text("bayes_prediction_lc", o.rtabmap.prediction_lc,
         "rtabmap: Bayes/PredictionLC, {virtual place, margin 0, 1, ...} (\"0.1 0.36 0.30 0.16 "
         "0.062 0.0151 0.00255 0.000324 2.5e-05 1.3e-06 4.8e-08 1.5e-09 4.5e-11\")");
  v.number("virtual_place_prior", o.rtabmap.virtual_place_prior,
           "rtabmap: Bayes/VirtualPlacePriorThr, P(no loop closure stays no loop closure) (0.9)");
  v.number("loop_threshold", o.rtabmap.loop_threshold,
           "rtabmap: Rtabmap/LoopThr, posterior at which the best hypothesis is verified (0.11)");
  v.integer("max_retrieved", o.rtabmap.max_retrieved,
            "rtabmap: Rtabmap/MaxRetrieved, LTM neighbours of the best hypothesis retrieved (2)");
  v.boolean(
      "proximity_by_space", o.rtabmap.proximity_by_space,
      "rtabmap: RGBD/ProximityBySpace, local loop closures with WM nodes near the position (true)");
  v.number("local_radius_m", o.rtabmap.local_radius_m,
           "rtabmap: RGBD/LocalRadius, proximity search radius around the estimated position (10)");
  v.integer(
      "proximity_max_graph_depth", o.rtabmap.proximity_max_graph_depth,
      "rtabmap: RGBD/ProximityMaxGraphDepth, proximity nodes at most this many links away (50)");
  v.integer("proximity_max_paths", o.rtabmap.proximity_max_paths,
            "rtabmap: RGBD/ProximityMaxPaths, paths of nearby nodes verified, one node each; 0 = "
            "all (3)");
  v.number("proximity_filtering_radius_m", o.rtabmap.proximity_filtering_radius_m,
           "rtabmap: RGBD/ProximityPathFilteringRadius, a path's node is verified this close (1)");
  v.number("proximity_angle_deg", o.rtabmap.proximity_angle_deg,
           "rtabmap: RGBD/ProximityAngle, most heading difference of a proximity node (45)");
  v.number(
      "optimize_max_error", o.rtabmap.optimize_max_error,
      "rtabmap: RGBD/OptimizeMaxError, link error (own sigmas) that rejects a loop closure (3)");
  v.number("time_threshold_ms", o.rtabmap.time_threshold_ms,
           "rtabmap: Rtabmap/TimeThr (ms), over it WM nodes move to LTM; inf = off (RTAB-Map: 0)",
           options::Infinity::kAllowed);
  v.choice("time_source", o.rtabmap.time_source, frontend::rtabmap::rtabmap_time_sources(),
           "rtabmap: what TimeThr is compared with: cost (deterministic cost model) or wall");
  v.number("cost_ms_per_node", o.rtabmap.cost.ms_per_node, "rtabmap cost model: fixed ms per node");
  v.number("cost_ms_per_word_comparison", o.rtabmap.cost.ms_per_word_comparison,
           "rtabmap cost model: ms per descriptor-word distance of the vocabulary search");
  v.number("cost_ms_per_likelihood_term", o.rtabmap.cost.ms_per_likelihood_term,
           "rtabmap cost model: ms per inverted-index reference of the likelihood");
  v.number("cost_ms_per_scored_node", o.rtabmap.cost.ms_per_scored_node,
           "rtabmap cost model: ms per WM node the likelihood scores");
  v.number("cost_ms_per_hypothesis", o.rtabmap.cost.ms_per_hypothesis,
           "rtabmap cost model: ms per Bayes filter hypothesis");
  v.number("cost_ms_per_verification", o.rtabmap.cost.ms_per_verification,
           "rtabmap cost model: ms per visual verification");
  v.integer("wifi_max_retrieved", o.rtabmap.wifi_max_retrieved,
            "rtabmap with Wi-Fi: LTM nodes of similar clusters retrieved per node (0 = all)");
  v.integer("wifi_max_immune", o.rtabmap.wifi_max_immune,
            "rtabmap with Wi-Fi: WM nodes of similar clusters immune to transfer, most similar "
            "cluster first (0 = all)");
  v.text("vocabulary", o.orbslam.vocabulary,
         "orbslam: vocabulary file (wifislam vocab train); empty = the shipped orb_k10_l4");
  v.integer("local_keyframes", o.orbslam.local_keyframes,
            "orbslam: best covisible keyframes of the previous keyframe verified per keyframe "
            "(LocalMapping: 10)");
  v.integer("covisibility_min_weight", o.orbslam.covisibility_min_weight,
            "orbslam: inliers for two keyframes to be covisible (ORB-SLAM: 15)");
  v.integer("covisibility_group_size", o.orbslam.covisibility_group_size,
            "orbslam: best covisible keyframes grouped with a loop candidate (10)");
  v.integer("loop_consistency", o.orbslam.loop_consistency,
            "orbslam: consecutive keyframes a loop candidate group must stay consistent (3)");
  v.integer("keyframes_between_loops", o.orbslam.keyframes_between_loops,
            "orbslam: keyframes after a loop closure before loop detection runs again (10)");
  v.integer("bow_min_matches", o.orbslam.bow_min_matches,
            "orbslam: SearchByBoW matches a loop candidate needs before verification (20)");
  v.integer("optimizer_iterations", o.graph.max_iterations, "iterations of the final optimisation");
  v.integer("optimizer_incremental_iterations", o.graph.incremental_max_iterations,
            "iterations after each loop closure");
  v.integer("optimizer_threads", o.graph.threads, "Ceres residual evaluation threads");
}

/// Sets one option from text ("min_matches", "15") by the rules of core/option_table.hpp. Throws
/// ParseError naming the key (the closest and every valid key when it is unknown) or the value
/// when it does not read as the option's type. `flag`: the option the text came from, named in the
/// error (`--set`, or `--sweep` for a value of a sweep).
void set_option(SlamOptions& options, const std::string& key, const std::string& value,
                const char* flag = "--set");

/// Parses "key=value" (a `--set`) and calls set_option. `frontend=` must name the front end
/// `options` already has (--frontend's, set first): a conflict is a ParseError, not a silent
/// override.
void set_option_assignment(SlamOptions& options, const std::string& assignment);

/// Checks ranges (min_matches >= 4, 0 < ransac_confidence < 1, ...); throws InvalidInputError.
void validate(const SlamOptions& options);

/// All options as a flat JSON object keyed like visit_options (for run.json).
nlohmann::json to_json(const SlamOptions& options);

/// Every `--set` key with its default and meaning, in visit_options order (the reference
/// `wifislam slam --help` prints).
std::string option_reference();

/// The front end option `key` is for ("orbslam" for vocabulary: its help reads "orbslam: ...",
/// "rtabmap with Wi-Fi: ..." is rtabmap's), or empty for an option every front end reads.
std::string option_front_end(const std::string& key);

/// One line per option of `keys` that is for a front end none of `frontends` is: setting it
/// changes nothing ("vocabulary is an orbslam option; the rgbdslam front end does not read it").
/// Nothing when a front end is an external system ("external:..."), which reads none of them.
std::vector<std::string> unread_option_warnings(const std::vector<std::string>& keys,
                                                const std::vector<std::string>& frontends);

}  // namespace wifislam::slam
