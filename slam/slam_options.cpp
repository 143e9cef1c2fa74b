#include "slam/slam_options.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.hpp"
#include "core/option_table_json.hpp"

namespace wifislam::slam {

void set_option(SlamOptions& options, const std::string& key, const std::string& value,
                const char* flag) {
  options::set_from_text(options, flag, "SLAM option", key, value);
}

void set_option_assignment(SlamOptions& options, const std::string& assignment) {
  const auto [key, value] = options::split_assignment("--set", assignment);
  // --frontend chose the front end before the assignments: a `--set frontend=` naming another
  // one would win silently over what the user asked for by its own flag.
  if (key == "frontend" && value != options.frontend) {
    throw ParseError("--set", assignment,
                     fmt::format("conflicts with --frontend {}: choose the front end with "
                                 "--frontend {} alone",
                                 options.frontend, value));
  }
  set_option(options, key, value);
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
  // Corners are intensity differences of 8-bit images: a threshold above 255 finds none.
  require(o.features.fast_threshold >= 0 && o.features.fast_threshold <= 255,
          fmt::format("fast_threshold must be in [0, 255], got {}", o.features.fast_threshold));
  require(o.features.min_depth_m >= 0 && o.features.max_depth_m > o.features.min_depth_m,
          "min_depth_m/max_depth_m must satisfy 0 <= min < max");
  require(o.transform.matching.ratio > 0 && o.transform.matching.ratio <= 1,
          "match_ratio must be in (0, 1]");
  // ORB descriptors are 256 bits: below 0 nothing matches, above 256 is no limit.
  require(o.transform.matching.max_hamming_distance >= 0 &&
              o.transform.matching.max_hamming_distance <= 256,
          fmt::format("max_hamming_distance must be in [0, 256], got {}",
                      o.transform.matching.max_hamming_distance));
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
  require(o.rgbdslam.optimizer_convergence >= 0 && std::isfinite(o.rgbdslam.optimizer_convergence),
          "optimizer_convergence must be a number >= 0");
  require(o.rgbdslam.wifi_long_term_candidates >= -1, "wifi_long_term_candidates must be >= -1");
  require(o.rgbdslam.robust_kernel_chi2 > 0 && std::isfinite(o.rgbdslam.robust_kernel_chi2),
          "robust_kernel_chi2 must be a positive number");
  for (double chi2 : o.rgbdslam.prune_chi2)
    require(chi2 > 0 && std::isfinite(chi2), "prune_chi2 must list positive chi^2 thresholds");
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
  // With no short-term memory the newest node would be in WM at once, a candidate of itself.
  require(o.rtabmap.stm_size >= 1, "stm_size must be >= 1");
  require(o.rtabmap.rehearsal_similarity >= 0, "rehearsal_similarity must be >= 0");
  require(o.rtabmap.max_features >= 1, "kp_max_features must be >= 1");
  require(o.rtabmap.nndr_ratio > 0 && o.rtabmap.nndr_ratio <= 1, "kp_nndr_ratio must be in (0, 1]");
  frontend::rtabmap::parse_prediction_lc("bayes_prediction_lc", o.rtabmap.prediction_lc);
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
  // Received powers lie far inside this: a floor above 0 dBm or far below any receiver's
  // sensitivity weights every AP alike (or none), which turned clustering off without a word.
  require(o.wifi.floor_dbm >= -150 && o.wifi.floor_dbm <= 0,
          fmt::format("wifi_floor_dbm must be in [-150, 0] dBm, got {}", o.wifi.floor_dbm));
  require(o.wifi.pause_gap_s > 0, "wifi_pause_gap_s must be > 0");
  require(o.wifi.pause_motion_m > 0, "wifi_pause_motion_m must be > 0");
}

nlohmann::json to_json(const SlamOptions& options) {
  return options::to_json<nlohmann::json>(options);
}

std::string option_reference() { return options::reference<SlamOptions>(); }

std::string option_front_end(const std::string& key) {
  for (const auto& [k, help] : options::option_help<SlamOptions>()) {
    if (k != key) continue;
    // "rtabmap: ...", "rtabmap with Wi-Fi: ...", "rtabmap cost model: ...".
    for (const std::string frontend : {"rgbdslam", "rtabmap", "orbslam"}) {
      if (help.rfind(frontend, 0) == 0 && help.size() > frontend.size() &&
          (help[frontend.size()] == ':' || help[frontend.size()] == ' '))
        return frontend;
    }
    return {};
  }
  return {};
}

std::vector<std::string> unread_option_warnings(const std::vector<std::string>& keys,
                                                const std::vector<std::string>& frontends) {
  std::vector<std::string> out;
  for (const std::string& f : frontends)
    if (f.rfind("external:", 0) == 0) return out;
  for (const std::string& key : keys) {
    const std::string owner = option_front_end(key);
    if (owner.empty() || std::find(frontends.begin(), frontends.end(), owner) != frontends.end())
      continue;
    out.push_back(fmt::format(
        "{} is an option of the {} front end; {} it, so it changes nothing", key, owner,
        frontends.size() == 1 ? frontends.front() + " does not read"
                              : fmt::format("none of {} reads", fmt::join(frontends, ", "))));
  }
  return out;
}

}  // namespace wifislam::slam
