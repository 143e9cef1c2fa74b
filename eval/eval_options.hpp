#pragma once
// Every threshold of the evaluation, with its default and why (docs/evaluation.md). All of them are
// written into metrics.json, metrics.csv and report.md, so a number is never read without the rule
// that produced it. `wifislam eval --set key=value` changes them.

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/option_table.hpp"
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

/// The names of the alignment modes (`align`).
options::Choices<AlignmentMode> alignment_modes();

/// Every threshold of `o` (core/option_table.hpp), in the order metrics.json and report.md list
/// them. A data table: one line per option.
template <class V>
void visit_options(V& v, EvalOptions& o) {
  v.number("max_time_difference_s", o.max_time_difference_s,
           "pair estimated and ground-truth stamps closer than this (s)");
  v.number("time_offset_s", o.time_offset_s,
           "added to the estimate's stamps before pairing (s, evaluate_ate.py --offset)");
  v.choice("align", o.align, alignment_modes(),
           "move the estimate onto ground truth: none, se3 (rigid) or sim3 (with scale)");
  v.number("rpe_delta_m", o.rpe_delta_m, "RPE over this ground-truth path length (m)");
  v.number("overlap_max_distance_m", o.overlap_max_distance_m,
           "views farther apart than this never overlap (m)");
  v.number("overlap_max_angle_deg", o.overlap_max_angle_deg,
           "views turned more than this never overlap (deg)");
  v.integer("overlap_sample_stride_px", o.overlap_sample_stride_px,
            "depth samples back-projected on a grid of this step (px)");
  v.integer("overlap_lookup_stride_px", o.overlap_lookup_stride_px,
            "the other view's depth looked up on a grid of this step (px)");
  v.number("overlap_depth_tolerance_m", o.overlap_depth_tolerance_m,
           "depth agreement, absolute part (m)");
  v.number("overlap_depth_tolerance_rel", o.overlap_depth_tolerance_rel,
           "depth agreement, relative part (fraction of depth)");
  v.number("overlap_min_fraction", o.overlap_min_fraction,
           "views overlap when this fraction of samples lands in the other view");
  v.number("revisit_min_path_m", o.revisit_min_path_m,
           "a true revisit needs this much ground-truth travel between the keyframes (m)");
  v.integer("episode_max_gap_keyframes", o.episode_max_gap_keyframes,
            "keyframes without partner tolerated inside one revisit episode");
  v.number("loop_max_translation_error_m", o.loop_max_translation_error_m,
           "correct loop closure: relative translation error at most this (m)");
  v.number("loop_max_rotation_error_deg", o.loop_max_rotation_error_deg,
           "correct loop closure: relative rotation error at most this (deg)");
  v.number("right_place_max_distance_m", o.right_place_max_distance_m,
           "right place, imprecise: keyframes truly at most this far apart (m)");
  v.number("right_place_max_translation_error_m", o.right_place_max_translation_error_m,
           "right place, imprecise: relative translation error at most this (m)");
  v.number("right_place_max_rotation_error_deg", o.right_place_max_rotation_error_deg,
           "right place, imprecise: relative rotation error at most this (deg)");
  v.number("far_distance_m", o.far_distance_m,
           "far wrong-place closure: keyframes truly farther apart than this (m)");
}

/// Names of the options `set_option` accepts, each with a one-line description.
std::vector<std::pair<std::string, std::string>> option_descriptions();

/// Applies "key=value" by the rules of core/option_table.hpp (`align` takes none / se3 / sim3).
/// Throws ParseError naming the key (unknown key, with the closest; a value that does not read as
/// the option's type) or InvalidInputError when the value is out of range; `options` is then
/// unchanged. `flag`: where the text came from, named in errors (`--set`, or the Python module's
/// `settings`).
void set_option(EvalOptions& options, const std::string& assignment, const char* flag = "--set");
/// The same for a key and its value given apart (the Python module's `settings`): a key holding
/// '=' is a key, unknown, not a key and a value.
void set_option(EvalOptions& options, const std::string& key, const std::string& value,
                const char* flag);

/// Throws InvalidInputError when a value is out of its range.
void validate(const EvalOptions& options);

}  // namespace wifislam::eval
