#include "slam/slam_options.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <type_traits>

#include <fmt/format.h>

#include "core/error.hpp"
#include "slam/optimize/edge_pruning.hpp"

namespace wifislam::slam {

std::vector<OptionField> option_fields(SlamOptions& o) {
  return {
      {"frontend", &o.frontend, "SLAM front end (memory, candidates, acceptance)"},
      {"seed", &o.seed, "seed of every random draw"},
      {"wifi", &o.wifi.enabled, "Wi-Fi module held by the front end (clustering, bounding)"},
      {"wifi_similarity", &o.wifi.similarity,
       "cosine similarity at or above which signatures are similar"},
      {"wifi_floor_dbm", &o.wifi.floor_dbm, "RSSI floor: weight = max(0, rssi - floor) (dBm)"},
      {"wifi_pause_gap_s", &o.wifi.pause_gap_s, "scan gap that ends a pause (s)"},
      {"wifi_pause_motion_m", &o.wifi.pause_motion_m, "odometry motion that ends a pause (m)"},
      {"max_keypoints", &o.features.max_keypoints, "ORB keypoints per frame"},
      {"orb_scale_factor", &o.features.scale_factor, "ORB pyramid scale step"},
      {"orb_levels", &o.features.pyramid_levels, "ORB pyramid levels"},
      {"fast_threshold", &o.features.fast_threshold, "FAST corner threshold"},
      {"min_depth_m", &o.features.min_depth_m, "nearest usable depth reading (m)"},
      {"max_depth_m", &o.features.max_depth_m, "farthest usable depth reading (m)"},
      {"match_ratio", &o.transform.matching.ratio, "Lowe ratio test threshold"},
      {"max_hamming_distance", &o.transform.matching.max_hamming_distance,
       "largest accepted descriptor distance"},
      {"min_matches", &o.transform.min_matches,
       "minimum RANSAC inliers to accept a transformation (the paper's min_matches: agreeing "
       "features; RGBDSLAMv2 also gates on raw matches, see visual_transformation.hpp)"},
      {"inlier_distance", &o.transform.inlier_distance,
       "RANSAC inlier threshold: reprojection error (px)"},
      {"ransac_iterations", &o.transform.ransac_iterations, "maximum RANSAC iterations"},
      {"ransac_confidence", &o.transform.ransac_confidence, "RANSAC stopping confidence (< 1)"},
      {"min_reprojection_sigma_px", &o.transform.min_reprojection_sigma_px,
       "floor of the reprojection noise in the information matrix (px)"},
      {"information_scale", &o.transform.information_scale,
       "multiplies visual edges' information so correct edges' chi^2 follows chi^2(6) (measured)"},
      {"depth_noise_coeff_per_m", &o.transform.depth_noise_coeff_per_m,
       "depth noise sigma_z = coeff z^2 in the information matrix (1/m)"},
      {"depth_consistency_sigmas", &o.transform.depth_consistency_sigmas,
       "depth agreement required of inliers with depth in both frames (sigmas; 0 = off)"},
      {"keyframe_min_inliers", &o.tracking.keyframe_min_inliers,
       "new keyframe when tracking inliers drop below"},
      {"keyframe_max_translation_m", &o.tracking.keyframe_max_translation_m,
       "new keyframe after this much translation (m)"},
      {"keyframe_max_rotation_rad", &o.tracking.keyframe_max_rotation_rad,
       "new keyframe after this much rotation (rad)"},
      {"loop_min_keyframe_gap", &o.tracking.loop_min_keyframe_gap,
       "keyframes back from which an accepted comparison is a loop closure"},
      {"loop_min_path_m", &o.tracking.loop_min_path_m,
       "estimated path length back from which an accepted comparison is a loop closure (m)"},
      {"relocalisation_keyframes", &o.tracking.relocalisation_keyframes,
       "recent keyframes tried when tracking is lost"},
      {"odometry_edges", &o.tracking.odometry_edges,
       "odometry edges between consecutive keyframes"},
      {"odometry_sigma_m", &o.tracking.odometry_sigma_m, "odometry edge translation sigma (m)"},
      {"odometry_sigma_rad", &o.tracking.odometry_sigma_rad, "odometry edge rotation sigma (rad)"},
      {"weak_sigma_m", &o.tracking.weak_sigma_m, "weak edge translation sigma (m)"},
      {"weak_sigma_rad", &o.tracking.weak_sigma_rad, "weak edge rotation sigma (rad)"},
      {"predecessor_candidates", &o.rgbdslam.predecessor_candidates,
       "rgbdslam: recent keyframes compared (RGBDSLAMv2: 4; before 2015: 2)"},
      {"neighbor_candidates", &o.rgbdslam.neighbor_candidates,
       "rgbdslam: geodesic neighbours sampled, weighted by id distance (4; before 2015: 2)"},
      {"geodesic_depth", &o.rgbdslam.geodesic_depth, "rgbdslam: graph depth of neighbours"},
      {"min_sampled_candidates", &o.rgbdslam.min_sampled_candidates,
       "rgbdslam: long-term candidates, random earlier keyframes (4; before 2015: 2)"},
      {"wifi_long_term_candidates", &o.rgbdslam.wifi_long_term_candidates,
       "rgbdslam with Wi-Fi: long-term candidates from similar clusters, best signature first "
       "(-1 = min_sampled_candidates, 0 = all)"},
      {"robust_kernel", &o.rgbdslam.robust_kernel,
       "rgbdslam: kernel on every edge: none, huber (RGBDSLAMv2), cauchy"},
      {"robust_kernel_chi2", &o.rgbdslam.robust_kernel_chi2,
       "rgbdslam: chi^2 where the kernel leaves the quadratic (4 x the last pruning stage)"},
      {"optimizer_skip_step", &o.rgbdslam.optimizer_skip_step,
       "rgbdslam: optimise the graph after every n-th keyframe too, not only after loop closures "
       "(RGBDSLAMv2: 1; 0 = after loop closures only)"},
      {"prune_chi2", &o.rgbdslam.prune_chi2,
       "rgbdslam: after-run pruning stages, chi^2 thresholds (RGBDSLAMv2's 5,1,0.25 rescaled to "
       "calibrated information: last = chi^2(6) 99.9 %); none = keep every edge"},
      {"detection_rate_hz", &o.rtabmap.detection_rate_hz,
       "rtabmap: Rtabmap/DetectionRate, most nodes per second; 0 = no time limit (1)"},
      {"linear_update_m", &o.rtabmap.linear_update_m,
       "rtabmap: RGBD/LinearUpdate, least translation since the last node for a new one (0.1)"},
      {"angular_update_rad", &o.rtabmap.angular_update_rad,
       "rtabmap: RGBD/AngularUpdate, least rotation since the last node for a new one (0.1)"},
      {"stm_size", &o.rtabmap.stm_size,
       "rtabmap: Mem/STMSize, newest nodes never searched for loop closures (10)"},
      {"rehearsal_similarity", &o.rtabmap.rehearsal_similarity,
       "rtabmap: Mem/RehearsalSimilarity, similarity with the previous node that merges (0.6)"},
      {"kp_max_features", &o.rtabmap.max_features,
       "rtabmap: Kp/MaxFeatures, strongest keypoints per node quantised into words (500)"},
      {"kp_nndr_ratio", &o.rtabmap.nndr_ratio,
       "rtabmap: Kp/NndrRatio, nearest-word distance ratio, else a new word (0.8)"},
      {"bayes_prediction_lc", &o.rtabmap.prediction_lc,
       "rtabmap: Bayes/PredictionLC, {virtual place, margin 0, 1, ...} (\"0.1 0.36 0.30 0.16 "
       "0.062 0.0151 0.00255 0.000324 2.5e-05 1.3e-06 4.8e-08 1.5e-09 4.5e-11\")"},
      {"virtual_place_prior", &o.rtabmap.virtual_place_prior,
       "rtabmap: Bayes/VirtualPlacePriorThr, P(no loop closure stays no loop closure) (0.9)"},
      {"loop_threshold", &o.rtabmap.loop_threshold,
       "rtabmap: Rtabmap/LoopThr, posterior at which the best hypothesis is verified (0.11)"},
      {"max_retrieved", &o.rtabmap.max_retrieved,
       "rtabmap: Rtabmap/MaxRetrieved, LTM neighbours of the best hypothesis retrieved (2)"},
      {"proximity_by_space", &o.rtabmap.proximity_by_space,
       "rtabmap: RGBD/ProximityBySpace, local loop closures with WM nodes near the position "
       "(true)"},
      {"local_radius_m", &o.rtabmap.local_radius_m,
       "rtabmap: RGBD/LocalRadius, proximity search radius around the estimated position (10)"},
      {"proximity_max_graph_depth", &o.rtabmap.proximity_max_graph_depth,
       "rtabmap: RGBD/ProximityMaxGraphDepth, proximity nodes at most this many links away (50)"},
      {"proximity_max_paths", &o.rtabmap.proximity_max_paths,
       "rtabmap: RGBD/ProximityMaxPaths, paths of nearby nodes verified, one node each; 0 = all "
       "(3)"},
      {"proximity_filtering_radius_m", &o.rtabmap.proximity_filtering_radius_m,
       "rtabmap: RGBD/ProximityPathFilteringRadius, a path's node is verified this close (1)"},
      {"proximity_angle_deg", &o.rtabmap.proximity_angle_deg,
       "rtabmap: RGBD/ProximityAngle, most heading difference of a proximity node (45)"},
      {"optimize_max_error", &o.rtabmap.optimize_max_error,
       "rtabmap: RGBD/OptimizeMaxError, link error (own sigmas) that rejects a loop closure (3)"},
      {"time_threshold_ms", &o.rtabmap.time_threshold_ms,
       "rtabmap: Rtabmap/TimeThr (ms), over it WM nodes move to LTM; inf = off (RTAB-Map: 0)"},
      {"time_source", &o.rtabmap.time_source,
       "rtabmap: what TimeThr is compared with: cost (deterministic cost model) or wall"},
      {"cost_ms_per_node", &o.rtabmap.cost.ms_per_node, "rtabmap cost model: fixed ms per node"},
      {"cost_ms_per_word_comparison", &o.rtabmap.cost.ms_per_word_comparison,
       "rtabmap cost model: ms per descriptor-word distance of the vocabulary search"},
      {"cost_ms_per_likelihood_term", &o.rtabmap.cost.ms_per_likelihood_term,
       "rtabmap cost model: ms per inverted-index reference of the likelihood"},
      {"cost_ms_per_scored_node", &o.rtabmap.cost.ms_per_scored_node,
       "rtabmap cost model: ms per WM node the likelihood scores"},
      {"cost_ms_per_hypothesis", &o.rtabmap.cost.ms_per_hypothesis,
       "rtabmap cost model: ms per Bayes filter hypothesis"},
      {"cost_ms_per_verification", &o.rtabmap.cost.ms_per_verification,
       "rtabmap cost model: ms per visual verification"},
      {"wifi_max_retrieved", &o.rtabmap.wifi_max_retrieved,
       "rtabmap with Wi-Fi: LTM nodes of similar clusters retrieved per node (0 = all)"},
      {"wifi_max_immune", &o.rtabmap.wifi_max_immune,
       "rtabmap with Wi-Fi: WM nodes of similar clusters immune to transfer, most similar "
       "cluster first (0 = all)"},
      {"vocabulary", &o.orbslam.vocabulary,
       "orbslam: vocabulary file (wifislam vocab train); empty = the shipped orb_k10_l4"},
      {"local_keyframes", &o.orbslam.local_keyframes,
       "orbslam: best covisible keyframes of the previous keyframe verified per keyframe "
       "(LocalMapping: 10)"},
      {"covisibility_min_weight", &o.orbslam.covisibility_min_weight,
       "orbslam: inliers for two keyframes to be covisible (ORB-SLAM: 15)"},
      {"covisibility_group_size", &o.orbslam.covisibility_group_size,
       "orbslam: best covisible keyframes grouped with a loop candidate (10)"},
      {"loop_consistency", &o.orbslam.loop_consistency,
       "orbslam: consecutive keyframes a loop candidate group must stay consistent (3)"},
      {"keyframes_between_loops", &o.orbslam.keyframes_between_loops,
       "orbslam: keyframes after a loop closure before loop detection runs again (10)"},
      {"bow_min_matches", &o.orbslam.bow_min_matches,
       "orbslam: SearchByBoW matches a loop candidate needs before verification (20)"},
      {"optimizer_iterations", &o.graph.max_iterations, "iterations of the final optimisation"},
      {"optimizer_incremental_iterations", &o.graph.incremental_max_iterations,
       "iterations after each loop closure"},
      {"optimizer_threads", &o.graph.threads, "Ceres residual evaluation threads"},
  };
}

namespace {

template <typename T>
bool parse_number(const std::string& text, T& out) {
  const char* begin = text.data();
  const char* end = begin + text.size();
  const auto [ptr, ec] = std::from_chars(begin, end, out);
  return ec == std::errc() && ptr == end;
}

/// Options where infinity means "off" (Rtabmap/TimeThr).
bool infinity_allowed(const std::string& key) { return key == "time_threshold_ms"; }

std::string known_keys(SlamOptions& options) {
  std::string keys;
  for (const OptionField& f : option_fields(options)) keys += (keys.empty() ? "" : ", ") + f.key;
  return keys;
}

}  // namespace

void set_option(SlamOptions& options, const std::string& key, const std::string& value) {
  for (const OptionField& field : option_fields(options)) {
    if (field.key != key) continue;
    const auto bad = [&](const char* expected) {
      return ParseError("--set", key, fmt::format("expected {}, got '{}'", expected, value));
    };
    if (auto* p = std::get_if<int*>(&field.target)) {
      if (!parse_number(value, **p)) throw bad("an integer");
    } else if (auto* p = std::get_if<double*>(&field.target)) {
      double v = 0;
      if (infinity_allowed(key) && (value == "inf" || value == "infinity")) {
        v = std::numeric_limits<double>::infinity();
      } else if (!parse_number(value, v) || !std::isfinite(v)) {
        throw bad(infinity_allowed(key) ? "a finite number or inf" : "a finite number");
      }
      **p = v;
    } else if (auto* p = std::get_if<std::uint64_t*>(&field.target)) {
      if (!parse_number(value, **p)) throw bad("a non-negative integer");
    } else if (auto* p = std::get_if<bool*>(&field.target)) {
      if (value == "true" || value == "1" || value == "on") {
        **p = true;
      } else if (value == "false" || value == "0" || value == "off") {
        **p = false;
      } else {
        throw bad("true or false");
      }
    } else if (auto* p = std::get_if<std::string*>(&field.target)) {
      **p = value;
    }
    return;
  }
  throw ParseError("--set", key, "unknown SLAM option; known: " + known_keys(options));
}

void set_option_assignment(SlamOptions& options, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw ParseError("--set", assignment, "expected key=value");
  }
  set_option(options, assignment.substr(0, eq), assignment.substr(eq + 1));
}

void validate(const SlamOptions& o) {
  const auto require = [](bool ok, const std::string& message) {
    if (!ok) throw InvalidInputError("SLAM option " + message);
  };
  // ORB ranges: beyond them OpenCV asserts (pyramid levels of zero pixels) or allocates without
  // bound. The coarsest level keeps at least 1/32 of the image (20 px of a 640 px frame).
  require(o.features.max_keypoints >= 8 && o.features.max_keypoints <= 100000,
          fmt::format("max_keypoints must be in [8, 100000], got {}", o.features.max_keypoints));
  require(o.features.scale_factor > 1.0 && o.features.scale_factor <= 2.0,
          fmt::format("orb_scale_factor must be in (1, 2], got {}", o.features.scale_factor));
  require(o.features.pyramid_levels >= 1 && o.features.pyramid_levels <= 32,
          fmt::format("orb_levels must be in [1, 32], got {}", o.features.pyramid_levels));
  require(std::pow(o.features.scale_factor, o.features.pyramid_levels - 1) <= 32.0 + 1e-9,
          fmt::format("orb_scale_factor^(orb_levels - 1) must be <= 32 (the coarsest pyramid "
                      "level keeps 1/32 of the image), got {}^{}",
                      o.features.scale_factor, o.features.pyramid_levels - 1));
  require(o.features.min_depth_m >= 0 && o.features.max_depth_m > o.features.min_depth_m,
          "min_depth_m/max_depth_m must satisfy 0 <= min < max");
  require(o.transform.matching.ratio > 0 && o.transform.matching.ratio <= 1,
          "match_ratio must be in (0, 1]");
  require(o.transform.min_matches >= 6, "min_matches must be >= 6 (PnP needs a few points)");
  require(o.transform.inlier_distance > 0, "inlier_distance must be > 0 (pixels)");
  require(o.transform.ransac_iterations >= 1, "ransac_iterations must be >= 1");
  require(o.transform.ransac_confidence > 0 && o.transform.ransac_confidence < 1,
          "ransac_confidence must be in (0, 1)");
  require(o.transform.min_reprojection_sigma_px > 0, "min_reprojection_sigma_px must be > 0");
  require(o.transform.information_scale > 0 && std::isfinite(o.transform.information_scale),
          "information_scale must be a positive number");
  require(o.transform.depth_noise_coeff_per_m >= 0, "depth_noise_coeff_per_m must be >= 0");
  require(o.transform.depth_consistency_sigmas >= 0, "depth_consistency_sigmas must be >= 0");
  require(o.tracking.keyframe_max_translation_m > 0, "keyframe_max_translation_m must be > 0");
  require(o.tracking.keyframe_max_rotation_rad > 0, "keyframe_max_rotation_rad must be > 0");
  require(o.tracking.loop_min_keyframe_gap >= 1, "loop_min_keyframe_gap must be >= 1");
  require(o.tracking.loop_min_path_m >= 0, "loop_min_path_m must be >= 0");
  require(o.tracking.relocalisation_keyframes >= 0, "relocalisation_keyframes must be >= 0");
  require(o.tracking.odometry_sigma_m > 0 && o.tracking.odometry_sigma_rad > 0 &&
              o.tracking.weak_sigma_m > 0 && o.tracking.weak_sigma_rad > 0,
          "edge sigmas must be > 0");
  require(o.rgbdslam.predecessor_candidates >= 1, "predecessor_candidates must be >= 1");
  require(o.rgbdslam.neighbor_candidates >= 0, "neighbor_candidates must be >= 0");
  require(o.rgbdslam.geodesic_depth >= 0, "geodesic_depth must be >= 0");
  require(o.rgbdslam.min_sampled_candidates >= 0, "min_sampled_candidates must be >= 0");
  require(o.rgbdslam.optimizer_skip_step >= 0, "optimizer_skip_step must be >= 0");
  require(o.rgbdslam.wifi_long_term_candidates >= -1, "wifi_long_term_candidates must be >= -1");
  require(o.rgbdslam.robust_kernel == "none" || o.rgbdslam.robust_kernel == "huber" ||
              o.rgbdslam.robust_kernel == "cauchy",
          "robust_kernel must be none, huber or cauchy, got '" + o.rgbdslam.robust_kernel + "'");
  require(o.rgbdslam.robust_kernel_chi2 > 0 && std::isfinite(o.rgbdslam.robust_kernel_chi2),
          "robust_kernel_chi2 must be a positive number");
  parse_chi2_thresholds("prune_chi2", o.rgbdslam.prune_chi2);  // throws naming the entry
  require(o.orbslam.local_keyframes >= 0, "local_keyframes must be >= 0");
  require(o.orbslam.covisibility_min_weight >= 1, "covisibility_min_weight must be >= 1");
  require(o.orbslam.covisibility_group_size >= 0, "covisibility_group_size must be >= 0");
  require(o.orbslam.loop_consistency >= 0, "loop_consistency must be >= 0");
  require(o.orbslam.keyframes_between_loops >= 0, "keyframes_between_loops must be >= 0");
  require(o.orbslam.bow_min_matches >= 0, "bow_min_matches must be >= 0");
  require(o.rtabmap.detection_rate_hz >= 0 && std::isfinite(o.rtabmap.detection_rate_hz),
          "detection_rate_hz must be a number >= 0");
  require(o.rtabmap.linear_update_m >= 0 && std::isfinite(o.rtabmap.linear_update_m),
          "linear_update_m must be a number >= 0");
  require(o.rtabmap.angular_update_rad >= 0 && std::isfinite(o.rtabmap.angular_update_rad),
          "angular_update_rad must be a number >= 0");
  require(o.rtabmap.stm_size >= 0, "stm_size must be >= 0");
  require(o.rtabmap.rehearsal_similarity >= 0, "rehearsal_similarity must be >= 0");
  require(o.rtabmap.max_features >= 1, "kp_max_features must be >= 1");
  require(o.rtabmap.nndr_ratio > 0 && o.rtabmap.nndr_ratio <= 1, "kp_nndr_ratio must be in (0, 1]");
  rtabmap::parse_prediction_lc("bayes_prediction_lc", o.rtabmap.prediction_lc);
  require(o.rtabmap.virtual_place_prior >= 0 && o.rtabmap.virtual_place_prior <= 1,
          "virtual_place_prior must be in [0, 1]");
  require(o.rtabmap.loop_threshold >= 0 && o.rtabmap.loop_threshold <= 1,
          "loop_threshold must be in [0, 1]");
  require(o.rtabmap.max_retrieved >= 0, "max_retrieved must be >= 0");
  require(o.rtabmap.optimize_max_error > 0, "optimize_max_error must be > 0");
  require(o.rtabmap.local_radius_m >= 0 && std::isfinite(o.rtabmap.local_radius_m),
          "local_radius_m must be a number >= 0");
  require(o.rtabmap.proximity_max_graph_depth >= 0, "proximity_max_graph_depth must be >= 0");
  require(o.rtabmap.proximity_max_paths >= 0, "proximity_max_paths must be >= 0");
  require(o.rtabmap.proximity_filtering_radius_m >= 0 &&
              std::isfinite(o.rtabmap.proximity_filtering_radius_m),
          "proximity_filtering_radius_m must be a number >= 0");
  require(o.rtabmap.proximity_angle_deg > 0 && o.rtabmap.proximity_angle_deg <= 180,
          "proximity_angle_deg must be in (0, 180]");
  require(o.rtabmap.time_threshold_ms > 0, "time_threshold_ms must be > 0 (inf = off)");
  require(o.rtabmap.time_source == "cost" || o.rtabmap.time_source == "wall",
          "time_source must be cost or wall, got '" + o.rtabmap.time_source + "'");
  require(o.rtabmap.cost.ms_per_node >= 0 && o.rtabmap.cost.ms_per_word_comparison >= 0 &&
              o.rtabmap.cost.ms_per_likelihood_term >= 0 && o.rtabmap.cost.ms_per_hypothesis >= 0 &&
              o.rtabmap.cost.ms_per_verification >= 0 && o.rtabmap.cost.ms_per_scored_node >= 0,
          "cost_ms_* must be >= 0");
  require(o.rtabmap.wifi_max_retrieved >= 0, "wifi_max_retrieved must be >= 0");
  require(o.rtabmap.wifi_max_immune >= 0, "wifi_max_immune must be >= 0");
  require(o.graph.max_iterations >= 1 && o.graph.incremental_max_iterations >= 0,
          "optimizer iterations must be >= 1 (final) and >= 0 (incremental)");
  require(o.graph.threads >= 1, "optimizer_threads must be >= 1");
  require(o.wifi.similarity >= -1 && o.wifi.similarity <= 1, "wifi_similarity must be in [-1, 1]");
  require(o.wifi.pause_gap_s > 0, "wifi_pause_gap_s must be > 0");
  require(o.wifi.pause_motion_m > 0, "wifi_pause_motion_m must be > 0");
}

nlohmann::json to_json(const SlamOptions& options) {
  SlamOptions copy = options;
  nlohmann::json out = nlohmann::json::object();
  for (const OptionField& f : option_fields(copy)) {
    std::visit(
        [&](auto* p) {
          if constexpr (std::is_same_v<decltype(p), double*>) {
            // JSON has no infinity; "inf" reads back through set_option.
            if (!std::isfinite(*p)) {
              out[f.key] = "inf";
              return;
            }
          }
          out[f.key] = *p;
        },
        f.target);
  }
  return out;
}

std::string option_reference() {
  SlamOptions defaults;
  const nlohmann::json values = to_json(defaults);
  std::string out;
  for (const OptionField& f : option_fields(defaults)) {
    const nlohmann::json& v = values.at(f.key);
    const std::string value = v.is_string() ? v.get<std::string>() : v.dump();
    out += fmt::format("  {}={}\n      {}\n", f.key, value, f.help);
  }
  return out;
}

}  // namespace wifislam::slam
