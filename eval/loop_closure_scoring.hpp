#pragma once
// Loop closures scored against exact ground truth (docs/evaluation.md; the
// paper's "False Positive/Negative in Computing Loop Closure").
//
// - Scored edges: every accepted edge of type visual or loop whose two keyframes lie at least
//   `revisit_min_path_m` of ground-truth path apart, whatever the front end called it (a
//   "visual" edge 10 m along the path to the wrong place closes a false loop all the same).
// - Verdict of a scored edge (loop_closure_verdict.hpp): correct, right_place_imprecise or
//   wrong_place, from its relative-pose error and its keyframes' true distance only. View
//   overlap is reported beside it but never decides it. FP% = wrong_place / scored edges.
// - Two sets: online (every scored edge, as accepted during the run) and after pruning (the
//   scored edges the after-run pruning kept; graph.json "pruned" false).
// - True revisit: keyframes i < j whose views overlap (view_overlap.hpp) with at least
//   `revisit_min_path_m` of ground-truth travel between them. Revisit episode: a maximal run of
//   consecutive keyframes j that have a true-revisit partner, allowing up to
//   `episode_max_gap_keyframes` keyframes without a partner inside one episode.
// - False negative: an episode that no correct edge of the set touches (either keyframe inside
//   the episode's keyframe span). FN% = FN / episodes, for each set.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/camera_intrinsics.hpp"
#include "core/pose.hpp"
#include "core/timestamp.hpp"
#include "eval/eval_options.hpp"
#include "eval/loop_closure_verdict.hpp"
#include "eval/view_overlap.hpp"

namespace wifislam::eval {

/// A keyframe of the run with its ground truth. Keyframe id = index.
struct KeyframeTruth {
  Timestamp time;
  Pose ground_truth = Pose::Identity();
  double path_m = 0.0;  // ground-truth path length from the first frame
};

/// An accepted edge between two keyframes, from graph.json or from a loop_closures.csv row.
struct AcceptedEdge {
  std::int64_t from_keyframe = -1, to_keyframe = -1;
  std::string type;  // graph.json's edge type; "loop" for a loop_closures.csv row
  std::string role;  // the candidate role from loop_closures.csv; "" when not known
  std::int64_t inliers = 0;
  Pose from_to = Pose::Identity();  // estimated pose of `to` in the camera frame of `from`
  bool pruned = false;              // removed by the after-run pruning
  double weight = 1.0;
  /// Where the edge was read and the keys of its ids, for errors: ("graph.json", "edges[4].from",
  /// "edges[4].to") or ("loop_closures.csv:5", "from_keyframe", "to_keyframe").
  std::string where, from_key, to_key;
};

struct ScoredLoopClosure {
  AcceptedEdge edge;
  ViewOverlap overlap;  // reported beside the verdict; never decides it
  double translation_error_m = 0.0;
  double rotation_error_deg = 0.0;
  double true_distance_m = 0.0;  // between the keyframes' ground-truth positions
  double path_between_m = 0.0;   // ground-truth travel between the two keyframes
  LoopClosureVerdict verdict = LoopClosureVerdict::kWrongPlace;
  bool far = false;  // wrong_place with the keyframes truly farther apart than far_distance_m
  int episode = -1;  // first revisit episode a correct closure touches, -1 = none

  bool correct() const { return verdict == LoopClosureVerdict::kCorrect; }
};

struct RevisitEpisode {
  std::int64_t first_keyframe = -1, last_keyframe = -1;
  std::int64_t revisiting_keyframes = 0;  // keyframes of the span that have a partner
  std::int64_t first_partner = -1;        // an earlier keyframe seeing what first_keyframe sees
  double first_partner_path_m = 0.0;      // travel between the two
  bool detected_online = false;           // touched by a correct edge
  bool detected_after_pruning = false;    // touched by a correct edge that survived pruning
};

/// The counts of one set of scored edges (online, or after pruning).
struct LoopClosureCounts {
  std::int64_t scored = 0, correct = 0, right_place_imprecise = 0, wrong_place = 0;
  std::int64_t far_wrong_place = 0;
  double false_positive_pct = 0.0;  // wrong_place / scored
  std::int64_t false_negatives = 0;
  double false_negative_pct = 0.0;  // false_negatives / episodes

  nlohmann::ordered_json to_json() const;
};

struct LoopClosureScore {
  std::vector<ScoredLoopClosure> closures;  // the scored edges, in input order
  std::vector<RevisitEpisode> episodes;
  LoopClosureCounts online, after_pruning;
  std::int64_t edges_considered = 0;  // visual and loop edges
  std::int64_t edges_short_path = 0;  // of those, under revisit_min_path_m apart: not scored
  std::int64_t revisit_keyframes = 0;
  std::int64_t pairs_tested = 0;          // pairs inside the geometric bound
  std::int64_t pairs_geometric_only = 0;  // of those, decided without depth
};

/// Depth of the keyframe at a time (null = none: geometric bound only).
using DepthLookup = std::function<const DepthView*(Timestamp)>;

/// `edges`: every accepted edge (odometry and weak ones are skipped). Throws ParseError at the
/// edge's `where` / key when it names a keyframe that keyframes.txt does not have.
LoopClosureScore score_loop_closures(const std::vector<KeyframeTruth>& keyframes,
                                     const std::vector<AcceptedEdge>& edges,
                                     const DepthLookup& depth, const CameraIntrinsics& intrinsics,
                                     const EvalOptions& options);

nlohmann::ordered_json to_json(const ScoredLoopClosure& closure,
                               const std::vector<KeyframeTruth>& keyframes);
nlohmann::ordered_json to_json(const RevisitEpisode& episode);

}  // namespace wifislam::eval
