#include "eval/requirement.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "core/did_you_mean.hpp"
#include "core/error.hpp"
#include "core/text_lines.hpp"
#include "eval/run_evaluation.hpp"

namespace wifislam::eval {

namespace {

// Two-character operators first, so "<=" is not read as "<" followed by "=0.5".
constexpr std::array<std::pair<std::string_view, Comparison>, 6> kOperators = {{
    {"<=", Comparison::kLessEqual},
    {">=", Comparison::kGreaterEqual},
    {"==", Comparison::kEqual},
    {"!=", Comparison::kNotEqual},
    {"<", Comparison::kLess},
    {">", Comparison::kGreater},
}};

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

std::string_view symbol(Comparison c) {
  for (const auto& [text, op] : kOperators)
    if (op == c) return text;
  return "?";
}

bool holds(double value, Comparison c, double bound) {
  switch (c) {
    case Comparison::kLessEqual:
      return value <= bound;
    case Comparison::kLess:
      return value < bound;
    case Comparison::kGreaterEqual:
      return value >= bound;
    case Comparison::kGreater:
      return value > bound;
    case Comparison::kEqual:
      return value == bound;
    case Comparison::kNotEqual:
      return value != bound;
  }
  return false;
}

std::vector<std::string> numeric_columns(const nlohmann::ordered_json& flat) {
  std::vector<std::string> names;
  for (const auto& [key, value] : flat.items())
    if (value.is_number() || value.is_null() || value.is_boolean()) names.push_back(key);
  return names;
}

}  // namespace

Requirement parse_requirement(std::string_view text) {
  const auto fail = [&](const std::string& why) {
    return InvalidInputError(fmt::format(
        "--require '{}': {} (expected METRIC OP NUMBER, OP one of <= < >= > == !=, METRIC a "
        "column of metrics.csv, e.g. 'ate_rmse_m<=0.5')",
        text, why));
  };
  for (const auto& [op_text, op] : kOperators) {
    const std::size_t at = text.find(op_text);
    if (at == std::string_view::npos) continue;
    Requirement r;
    r.text = std::string(text);
    r.comparison = op;
    r.metric = std::string(trimmed(text.substr(0, at)));
    const std::string_view bound = trimmed(text.substr(at + op_text.size()));
    if (r.metric.empty()) throw fail("no metric before " + std::string(op_text));
    if (r.metric.find_first_of("<>=!") != std::string::npos) throw fail("more than one operator");
    if (!parse_double(bound, r.bound) || !std::isfinite(r.bound))
      throw fail(fmt::format("'{}' is not a finite number", bound));
    return r;
  }
  throw fail("no comparison operator");
}

void check_metric_names(const std::vector<Requirement>& requirements,
                        const nlohmann::ordered_json& flat) {
  std::vector<std::string> known = RunEvaluation::flat_metric_names();
  for (const std::string& name : numeric_columns(flat)) known.push_back(name);
  for (const Requirement& r : requirements) {
    const bool is_text = flat.contains(r.metric) && flat[r.metric].is_string();
    if (std::find(known.begin(), known.end(), r.metric) != known.end() && !is_text) continue;
    if (is_text) {
      // A column that is there but holds text: suggesting its own name would be no help.
      throw InvalidInputError(
          fmt::format("--require '{}': '{}' holds text ('{}'), not a number: only numeric "
                      "columns of metrics.csv can be required",
                      r.text, r.metric, flat[r.metric].get<std::string>()));
    }
    throw InvalidInputError(
        fmt::format("--require '{}': '{}' is no numeric column of "
                    "metrics.csv{}",
                    r.text, r.metric, did_you_mean(r.metric, known)));
  }
}

std::vector<RequirementResult> check_requirements(const std::vector<Requirement>& requirements,
                                                  const nlohmann::ordered_json& flat) {
  check_metric_names(requirements, flat);
  std::vector<RequirementResult> results;
  for (const Requirement& r : requirements) {
    RequirementResult result;
    result.requirement = r;
    const nlohmann::ordered_json value =
        flat.contains(r.metric) ? flat[r.metric] : nlohmann::ordered_json();
    if (value.is_number()) result.value = value.get<double>();
    if (value.is_boolean()) result.value = value.get<bool>() ? 1.0 : 0.0;
    result.met =
        result.value && std::isfinite(*result.value) && holds(*result.value, r.comparison, r.bound);
    results.push_back(result);
  }
  return results;
}

std::string RequirementResult::describe() const {
  const Requirement& r = requirement;
  const std::string bound = format_double_exact(r.bound);
  if (!value) {
    return fmt::format("NOT met: {} {} {}: the run has no {} (not available)", r.metric,
                       symbol(r.comparison), bound, r.metric);
  }
  const std::string v = format_double_exact(*value);
  if (met) return fmt::format("met: {} = {} {} {}", r.metric, v, symbol(r.comparison), bound);
  const double by = std::abs(*value - r.bound);
  const char* side = *value > r.bound ? "above" : *value < r.bound ? "below" : "equal to";
  if (by == 0.0)
    return fmt::format("NOT met: {} = {}, equal to {} ({} {} {} fails)", r.metric, v, bound,
                       r.metric, symbol(r.comparison), bound);
  return fmt::format("NOT met: {} = {} ({} {} {} fails), {} {} by {}", r.metric, v, r.metric,
                     symbol(r.comparison), bound, side, bound, format_double_exact(by));
}

}  // namespace wifislam::eval
