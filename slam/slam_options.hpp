#pragma once
// Everything a SLAM run can be told (Ceres style: every field carries its default and says what it
// trades off). The CLI's `--set key=value` and run.json use the flat keys of option_fields(),
// which are the paper's and RGBDSLAMv2's parameter names where those exist.

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "slam/feature/orb_feature_extractor.hpp"
#include "slam/frontend/orbslam/orbslam_options.hpp"
#include "slam/frontend/rgbdslam/rgbdslam_front_end.hpp"
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
  WifiOptions wifi;
  /// Seed of every random draw of the run (e.g. RGBD-SLAM's random keyframes).
  std::uint64_t seed = 1;
  FeatureOptions features;
  VisualTransformOptions transform;
  TrackingOptions tracking;
  RgbdslamOptions rgbdslam;
  RtabmapOptions rtabmap;
  OrbslamOptions orbslam;
  PoseGraphOptions graph;
};

/// One settable option: flat key, where it lives, and what it means.
struct OptionField {
  std::string key;
  std::variant<int*, double*, bool*, std::string*, std::uint64_t*> target;
  std::string help;
};

/// Every settable option of `options` (pointers into it).
std::vector<OptionField> option_fields(SlamOptions& options);

/// Sets one option from text ("min_matches", "15"). Throws ParseError naming the key (and the
/// valid keys when it is unknown) or the value when it does not parse / is out of range.
void set_option(SlamOptions& options, const std::string& key, const std::string& value);

/// Parses "key=value" and calls set_option.
void set_option_assignment(SlamOptions& options, const std::string& assignment);

/// Checks ranges (min_matches >= 4, 0 < ransac_confidence < 1, ...); throws InvalidInputError.
void validate(const SlamOptions& options);

/// All options as a flat JSON object keyed like option_fields() (for run.json).
nlohmann::json to_json(const SlamOptions& options);

/// Every `--set` key with its default and meaning, one per line, in option_fields() order
/// (the reference `wifislam slam --help` prints).
std::string option_reference();

}  // namespace wifislam::slam
