#include "eval/eval_options.hpp"

#include <cmath>
#include <optional>
#include <type_traits>
#include <variant>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/text_lines.hpp"

namespace wifislam::eval {

namespace {

using Field = std::variant<double EvalOptions::*, int EvalOptions::*, bool EvalOptions::*,
                           AlignmentMode EvalOptions::*>;

struct OptionEntry {
  const char* name;
  Field field;
  const char* description;
};

const std::vector<OptionEntry>& entries() {
  static const std::vector<OptionEntry> table = {
      {"max_time_difference_s", &EvalOptions::max_time_difference_s,
       "pair estimated and ground-truth stamps closer than this (s)"},
      {"time_offset_s", &EvalOptions::time_offset_s,
       "added to the estimate's stamps before pairing (s, evaluate_ate.py --offset)"},
      {"align", &EvalOptions::align,
       "move the estimate onto ground truth: none, se3 (rigid) or sim3 (with scale)"},
      {"rpe_delta_m", &EvalOptions::rpe_delta_m, "RPE over this ground-truth path length (m)"},
      {"overlap_max_distance_m", &EvalOptions::overlap_max_distance_m,
       "views farther apart than this never overlap (m)"},
      {"overlap_max_angle_deg", &EvalOptions::overlap_max_angle_deg,
       "views turned more than this never overlap (deg)"},
      {"overlap_sample_stride_px", &EvalOptions::overlap_sample_stride_px,
       "depth samples back-projected on a grid of this step (px)"},
      {"overlap_lookup_stride_px", &EvalOptions::overlap_lookup_stride_px,
       "the other view's depth looked up on a grid of this step (px)"},
      {"overlap_depth_tolerance_m", &EvalOptions::overlap_depth_tolerance_m,
       "depth agreement, absolute part (m)"},
      {"overlap_depth_tolerance_rel", &EvalOptions::overlap_depth_tolerance_rel,
       "depth agreement, relative part (fraction of depth)"},
      {"overlap_min_fraction", &EvalOptions::overlap_min_fraction,
       "views overlap when this fraction of samples lands in the other view"},
      {"revisit_min_path_m", &EvalOptions::revisit_min_path_m,
       "a true revisit needs this much ground-truth travel between the keyframes (m)"},
      {"episode_max_gap_keyframes", &EvalOptions::episode_max_gap_keyframes,
       "keyframes without partner tolerated inside one revisit episode"},
      {"loop_max_translation_error_m", &EvalOptions::loop_max_translation_error_m,
       "correct loop closure: relative translation error at most this (m)"},
      {"loop_max_rotation_error_deg", &EvalOptions::loop_max_rotation_error_deg,
       "correct loop closure: relative rotation error at most this (deg)"},
      {"right_place_max_distance_m", &EvalOptions::right_place_max_distance_m,
       "right place, imprecise: keyframes truly at most this far apart (m)"},
      {"right_place_max_translation_error_m", &EvalOptions::right_place_max_translation_error_m,
       "right place, imprecise: relative translation error at most this (m)"},
      {"right_place_max_rotation_error_deg", &EvalOptions::right_place_max_rotation_error_deg,
       "right place, imprecise: relative rotation error at most this (deg)"},
      {"far_distance_m", &EvalOptions::far_distance_m,
       "far wrong-place closure: keyframes truly farther apart than this (m)"},
  };
  return table;
}

}  // namespace

nlohmann::ordered_json EvalOptions::to_json() const {
  nlohmann::ordered_json j;
  for (const OptionEntry& e : entries()) {
    std::visit(
        [&](auto member) {
          if constexpr (std::is_same_v<std::remove_cvref_t<decltype(this->*member)>,
                                       AlignmentMode>) {
            j[e.name] = eval::to_string(this->*member);
          } else {
            j[e.name] = this->*member;
          }
        },
        e.field);
  }
  return j;
}

std::vector<std::pair<std::string, std::string>> option_descriptions() {
  std::vector<std::pair<std::string, std::string>> out;
  for (const OptionEntry& e : entries()) out.emplace_back(e.name, e.description);
  return out;
}

void set_option(EvalOptions& options, const std::string& assignment) {
  const std::size_t eq = assignment.find('=');
  if (eq == std::string::npos) {
    throw InvalidInputError("--set '" + assignment + "': expected key=value");
  }
  const std::string key = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  for (const OptionEntry& e : entries()) {
    if (key != e.name) continue;
    EvalOptions updated = options;  // unchanged when the value is rejected
    if (std::holds_alternative<AlignmentMode EvalOptions::*>(e.field)) {
      const std::optional<AlignmentMode> mode = parse_alignment_mode(text);
      if (!mode) {
        throw InvalidInputError(
            fmt::format("--set {}: '{}' is not one of none, se3, sim3", key, text));
      }
      updated.*std::get<AlignmentMode EvalOptions::*>(e.field) = *mode;
      options = updated;
      return;
    }
    double value = 0.0;
    if (text == "true" || text == "false") {
      value = text == "true" ? 1.0 : 0.0;
    } else if (!parse_double(text, value) || !std::isfinite(value)) {
      throw InvalidInputError(fmt::format("--set {}: '{}' is not a number", key, text));
    }
    std::visit(
        [&](auto member) {
          using T = std::remove_reference_t<decltype(updated.*member)>;
          if constexpr (std::is_same_v<T, bool>) {
            if (value != 0.0 && value != 1.0)
              throw InvalidInputError(fmt::format("--set {}: expected 0/1/true/false", key));
            updated.*member = value != 0.0;
          } else if constexpr (std::is_same_v<T, int>) {
            if (value != std::round(value) || std::abs(value) > 1e9)
              throw InvalidInputError(fmt::format("--set {}: expected an integer", key));
            updated.*member = static_cast<int>(value);
          } else if constexpr (std::is_same_v<T, double>) {
            updated.*member = value;
          }
        },
        e.field);
    validate(updated);
    options = updated;
    return;
  }
  std::string known;
  for (const OptionEntry& e : entries()) known += (known.empty() ? "" : ", ") + std::string(e.name);
  throw InvalidInputError("--set " + key + ": unknown threshold (known: " + known + ")");
}

void validate(const EvalOptions& o) {
  auto require = [](bool ok, const char* key, const char* what) {
    if (!ok) throw InvalidInputError(fmt::format("eval option {}: must be {}", key, what));
  };
  require(o.max_time_difference_s > 0, "max_time_difference_s", "> 0");
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
  require(std::isfinite(o.time_offset_s), "time_offset_s", "a finite number");
  require(o.right_place_max_distance_m >= 0, "right_place_max_distance_m", ">= 0");
  require(o.right_place_max_translation_error_m >= 0, "right_place_max_translation_error_m",
          ">= 0");
  require(o.right_place_max_rotation_error_deg >= 0, "right_place_max_rotation_error_deg", ">= 0");
  require(o.far_distance_m >= 0, "far_distance_m", ">= 0");
}

}  // namespace wifislam::eval
