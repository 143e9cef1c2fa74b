#include "eval/loop_closure_verdict.hpp"

namespace wifislam::eval {

const char* to_string(LoopClosureVerdict verdict) {
  switch (verdict) {
    case LoopClosureVerdict::kCorrect:
      return "correct";
    case LoopClosureVerdict::kRightPlaceImprecise:
      return "right_place_imprecise";
    case LoopClosureVerdict::kWrongPlace:
      return "wrong_place";
  }
  return "wrong_place";
}

LoopClosureVerdict classify_loop_closure(double translation_error_m, double rotation_error_deg,
                                         double true_distance_m, const EvalOptions& o) {
  if (translation_error_m <= o.loop_max_translation_error_m &&
      rotation_error_deg <= o.loop_max_rotation_error_deg) {
    return LoopClosureVerdict::kCorrect;
  }
  if (true_distance_m <= o.right_place_max_distance_m &&
      translation_error_m <= o.right_place_max_translation_error_m &&
      rotation_error_deg <= o.right_place_max_rotation_error_deg) {
    return LoopClosureVerdict::kRightPlaceImprecise;
  }
  return LoopClosureVerdict::kWrongPlace;
}

bool is_far_wrong_place(LoopClosureVerdict verdict, double true_distance_m, const EvalOptions& o) {
  return verdict == LoopClosureVerdict::kWrongPlace && true_distance_m > o.far_distance_m;
}

}  // namespace wifislam::eval
