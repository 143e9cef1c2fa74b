#pragma once
// The verdict on one accepted loop-closure edge, from its relative-pose error and the true
// distance between its two keyframes only (view overlap never decides it: a closure a few
// centimetres from the truth is correct even where the overlap test is unsure). The paper's false
// positive is `kWrongPlace`.
//
//   correct                 error within loop_max_translation_error_m / loop_max_rotation_error_deg
//   right_place_imprecise   not correct, keyframes truly within right_place_max_distance_m, and
//                           error within right_place_max_translation_error_m / _rotation_error_deg
//   wrong_place             everything else ("far" when the keyframes truly stand farther apart
//                           than far_distance_m)

#include "eval/eval_options.hpp"

namespace wifislam::eval {

enum class LoopClosureVerdict { kCorrect, kRightPlaceImprecise, kWrongPlace };

/// "correct", "right_place_imprecise", "wrong_place".
const char* to_string(LoopClosureVerdict verdict);

LoopClosureVerdict classify_loop_closure(double translation_error_m, double rotation_error_deg,
                                         double true_distance_m, const EvalOptions& options);

/// A wrong-place verdict between keyframes truly farther apart than `far_distance_m`.
bool is_far_wrong_place(LoopClosureVerdict verdict, double true_distance_m,
                        const EvalOptions& options);

}  // namespace wifislam::eval
