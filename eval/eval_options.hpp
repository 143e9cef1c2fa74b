#pragma once
// Every threshold of the evaluation, with its default and why (DESIGN.md, "Ground truth and
// metrics"). All of them are written into metrics.json, metrics.csv and report.md, so a number is
// never read without the rule that produced it. `wifislam eval --set key=value` changes them.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "eval/alignment.hpp"

namespace wifislam::eval {

struct EvalOptions {
  // --- Trajectory error ------------------------------------------------------------------------
  /// Estimated and ground-truth poses are paired when their stamps differ by less than this
  /// (TUM associate.py / evaluate_ate.py --max_difference default).
  double max_time_difference_s = 0.02;
  /// Added to the estimate's stamps (trajectory and keyframes) before they are paired with ground
  /// truth: a clock offset between the two recorders (evaluate_ate.py --offset).
  double time_offset_s = 0.0;
  /// How the estimate is moved onto ground truth before ATE: Umeyama rigid (SE(3)) by default, as
  /// evaluate_ate.py does and as RGB-D needs (the depth sensor fixes the scale); Sim(3) for
  /// monocular-style estimates (evo -as); none when the estimate is already in the ground-truth
  /// frame.
  AlignmentMode align = AlignmentMode::kSe3;
  /// RPE pairs frame i with the first frame j whose ground-truth path length from i reaches this
  /// (a delta in metres, as evo's --delta_unit m). 1 m gives per-metre drift directly.
  double rpe_delta_m = 1.0;

  // --- View overlap (does keyframe B see what keyframe A sees?) --------------------------------
  /// Cheap geometric pre-check on the ground-truth poses: farther apart than this, or optical
  /// axes turned by more than `overlap_max_angle_deg`, the views are not compared pixel by pixel.
  /// 3 m is about the Kinect v1's useful depth range (0.8 - 4 m) minus a margin.
  double overlap_max_distance_m = 3.0;
  double overlap_max_angle_deg = 60.0;  // about the horizontal field of view (62 deg)
  /// Depth pixels of A back-projected (with A's ground-truth pose) on a grid of this step, in
  /// pixels. 8 px on 640 x 480 gives up to 4800 samples: plenty for a fraction to 1 %.
  int overlap_sample_stride_px = 8;
  /// B's depth is looked up on a grid of this step (nearest grid pixel); keeps memory per
  /// keyframe small (1/16 of the image at 4).
  int overlap_lookup_stride_px = 4;
  /// A sample "lands" in B when B's depth at its pixel agrees with the sample's depth in B within
  /// max(abs, rel x depth): Kinect noise at 4 m is ~2.3 cm, the grid lookup adds a few %.
  double overlap_depth_tolerance_m = 0.10;
  double overlap_depth_tolerance_rel = 0.05;
  /// Views overlap when the fraction of samples landing is at least this, in either direction
  /// (A in B or B in A: a close-up of a wall and a wide view of it share content both ways).
  /// 0.2 is well above what two views of different places reach by coincidence, and below what
  /// two views a feature matcher can relate reach.
  double overlap_min_fraction = 0.2;

  // --- Loop closures -----------------------------------------------------------------------------
  /// A pair of keyframes (i < j) is a true revisit when their views overlap and the robot
  /// travelled at least this far between them (ground-truth path length: standing still in a
  /// pause, or tracking the previous keyframe, is not a revisit).
  double revisit_min_path_m = 10.0;
  /// Consecutive revisiting keyframes form one episode; up to this many keyframes without a
  /// partner inside an episode do not split it (a turn or a blurred view in the middle).
  int episode_max_gap_keyframes = 2;
  /// An accepted loop-closure edge is correct when its estimated relative pose is within these
  /// of the ground-truth one inv(gt_from) * gt_to (the pose decides, not view overlap). 0.3 m /
  /// 5 deg: a correct RANSAC estimate on our renders is within centimetres; a wrong one is off by
  /// metres.
  double loop_max_translation_error_m = 0.3;
  double loop_max_rotation_error_deg = 5.0;
  /// Not correct, but the right place: the two keyframes truly stand within this of each other
  /// and the pose error is within the looser bounds below. Such an edge bends the map a little
  /// instead of tearing it; it is not the paper's false positive. 3 m = the view-overlap range.
  double right_place_max_distance_m = 3.0;
  double right_place_max_translation_error_m = 1.0;
  double right_place_max_rotation_error_deg = 10.0;
  /// A wrong-place edge whose keyframes truly stand farther apart than this is "far": it joins
  /// another part of the building (the aliasing case), not a near miss. 12 m is more than a
  /// corridor wing's length in our scenes, well past the right-place range.
  double far_distance_m = 12.0;

  /// The thresholds as JSON (key -> value), in declaration order.
  nlohmann::ordered_json to_json() const;
};

/// Names of the options `set_option` accepts, each with a one-line description.
std::vector<std::pair<std::string, std::string>> option_descriptions();

/// Applies "key=value" (`align` takes none / se3 / sim3). Throws InvalidInputError naming the key
/// (unknown key, value not a number, out of range).
void set_option(EvalOptions& options, const std::string& assignment);

/// Throws InvalidInputError when a value is out of its range.
void validate(const EvalOptions& options);

}  // namespace wifislam::eval
