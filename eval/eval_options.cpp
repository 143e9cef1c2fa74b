#include "eval/eval_options.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/option_table_json.hpp"

namespace wifislam::eval {

options::Choices<AlignmentMode> alignment_modes() {
  return {
      {AlignmentMode::kNone, "none"}, {AlignmentMode::kSe3, "se3"}, {AlignmentMode::kSim3, "sim3"}};
}

nlohmann::ordered_json EvalOptions::to_json() const {
  return options::to_json<nlohmann::ordered_json>(*this);
}

std::vector<std::pair<std::string, std::string>> option_descriptions() {
  return options::option_help<EvalOptions>();
}

void set_option(EvalOptions& options, const std::string& assignment, const char* flag) {
  const auto [key, text] = options::split_assignment(flag, assignment);
  set_option(options, key, text, flag);
}

void set_option(EvalOptions& options, const std::string& key, const std::string& value,
                const char* flag) {
  EvalOptions updated = options;  // unchanged when the value is rejected
  options::set_from_text(updated, flag, "evaluation threshold", key, value);
  validate(updated);
  options = updated;
}

void validate(const EvalOptions& o) {
  auto require = [](bool ok, const char* key, const char* what) {
    if (!ok) throw InvalidInputError(fmt::format("eval option {}: must be {}", key, what));
  };
  // Stamps are whole nanoseconds in 64 bits (to 2262): a difference or an offset beyond these
  // bounds overflowed them and associated nothing, without a word.
  require(o.max_time_difference_s > 0 && o.max_time_difference_s <= 1e6, "max_time_difference_s",
          "in (0, 1e6] s");
  require(o.rpe_delta_m > 0, "rpe_delta_m", "> 0");
  require(o.overlap_max_distance_m > 0, "overlap_max_distance_m", "> 0");
  require(o.overlap_max_angle_deg > 0 && o.overlap_max_angle_deg <= 180, "overlap_max_angle_deg",
          "in (0, 180]");
  require(o.overlap_sample_stride_px >= 1, "overlap_sample_stride_px", ">= 1");
  require(o.overlap_lookup_stride_px >= 1, "overlap_lookup_stride_px", ">= 1");
  require(o.overlap_depth_tolerance_m >= 0, "overlap_depth_tolerance_m", ">= 0");
  require(o.overlap_depth_tolerance_rel >= 0, "overlap_depth_tolerance_rel", ">= 0");
  require(o.overlap_min_fraction > 0 && o.overlap_min_fraction <= 1, "overlap_min_fraction",
          "in (0, 1]");
  require(o.revisit_min_path_m >= 0, "revisit_min_path_m", ">= 0");
  require(o.episode_max_gap_keyframes >= 0, "episode_max_gap_keyframes", ">= 0");
  require(o.loop_max_translation_error_m > 0, "loop_max_translation_error_m", "> 0");
  require(o.loop_max_rotation_error_deg > 0, "loop_max_rotation_error_deg", "> 0");
  require(std::abs(o.time_offset_s) <= 1e9, "time_offset_s", "in [-1e9, 1e9] s");
  require(o.right_place_max_distance_m >= 0, "right_place_max_distance_m", ">= 0");
  require(o.right_place_max_translation_error_m >= 0, "right_place_max_translation_error_m",
          ">= 0");
  require(o.right_place_max_rotation_error_deg >= 0, "right_place_max_rotation_error_deg", ">= 0");
  require(o.far_distance_m >= 0, "far_distance_m", ">= 0");
}

}  // namespace wifislam::eval
