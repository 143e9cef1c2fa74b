#pragma once
// Loop closures scored against exact ground truth (DESIGN.md, "Ground truth and metrics"; the
// paper's "False Positive/Negative in Computing Loop Closure").
//
// - True revisit: keyframes i < j of the run whose views overlap (view_overlap.hpp) and between
//   which the robot travelled at least `revisit_min_path_m` (ground-truth path length).
// - Revisit episode: a maximal run of consecutive keyframes j that have a true-revisit partner,
//   allowing up to `episode_max_gap_keyframes` keyframes without a partner inside one episode.
// - A detected loop closure is correct when its keyframes' views overlap and its estimated
//   relative pose is within `loop_max_translation_error_m` / `loop_max_rotation_error_deg` of the
//   ground-truth inv(gt_from) * gt_to; otherwise it is a false positive. FP% = FP / detected.
// - A false negative is an episode that no correct loop closure touches (either keyframe of the
//   closure inside the episode's keyframe span). FN% = FN / episodes.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/camera_intrinsics.hpp"
#include "core/pose.hpp"
#include "core/timestamp.hpp"
#include "eval/eval_options.hpp"
#include "eval/loop_closure_csv.hpp"
#include "eval/view_overlap.hpp"

namespace wifislam::eval {

/// A keyframe of the run with its ground truth. Keyframe id = index.
struct KeyframeTruth {
  Timestamp time;
  Pose ground_truth = Pose::Identity();
  double path_m = 0.0;  // ground-truth path length from the first frame
};

struct ScoredLoopClosure {
  DetectedLoopClosure detected;
  ViewOverlap overlap;
  double translation_error_m = 0.0;
  double rotation_error_deg = 0.0;
  double path_between_m = 0.0;  // ground-truth travel between the two keyframes
  bool correct = false;
  std::string verdict;  // "correct", or why not
  int episode = -1;     // index of the revisit episode it touches, -1 = none
};

struct RevisitEpisode {
  std::int64_t first_keyframe = -1, last_keyframe = -1;
  std::int64_t revisiting_keyframes = 0;  // keyframes of the span that have a partner
  std::int64_t first_partner = -1;        // an earlier keyframe seeing what first_keyframe sees
  double first_partner_path_m = 0.0;      // travel between the two
  bool detected = false;                  // touched by a correct loop closure
};

struct LoopClosureScore {
  std::vector<ScoredLoopClosure> closures;
  std::vector<RevisitEpisode> episodes;
  std::int64_t detected = 0, correct = 0, false_positives = 0;
  std::int64_t revisit_keyframes = 0, false_negatives = 0;
  double false_positive_pct = 0.0, false_negative_pct = 0.0;
  std::int64_t pairs_tested = 0;          // pairs inside the geometric bound
  std::int64_t pairs_geometric_only = 0;  // of those, decided without depth
};

/// Depth of the keyframe at a time (null = none: geometric bound only).
using DepthLookup = std::function<const DepthView*(Timestamp)>;

/// Throws ParseError naming loop_closures.csv's line when a closure names a keyframe that
/// keyframes.txt does not have.
LoopClosureScore score_loop_closures(const std::vector<KeyframeTruth>& keyframes,
                                     const std::vector<DetectedLoopClosure>& detected,
                                     const std::string& loop_closures_file,
                                     const DepthLookup& depth, const CameraIntrinsics& intrinsics,
                                     const EvalOptions& options);

nlohmann::ordered_json to_json(const ScoredLoopClosure& closure);
nlohmann::ordered_json to_json(const RevisitEpisode& episode);

}  // namespace wifislam::eval
