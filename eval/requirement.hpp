#pragma once
// Requirements on an evaluation (`wifislam eval --require 'ate_rmse_m<=0.5'`): what makes the
// harness another project's regression test. A requirement names a column of metrics.csv (the
// flat metrics row), a comparison (<=, <, >=, >, ==, !=) and a number. A requirement on a metric
// the run does not have (loop closures of a trajectory file) is not met: a regression test must
// not pass for want of data.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace wifislam::eval {

enum class Comparison { kLessEqual, kLess, kGreaterEqual, kGreater, kEqual, kNotEqual };

struct Requirement {
  std::string metric;
  Comparison comparison = Comparison::kLessEqual;
  double bound = 0.0;
  std::string text;  // as given, for messages
};

/// Parses "metric OP number" (spaces allowed around OP). Throws InvalidInputError naming the
/// text for anything else (no operator, an empty metric, a bound that is not a finite number).
Requirement parse_requirement(std::string_view text);

/// Throws InvalidInputError for a requirement naming no numeric column a metrics.csv row can
/// have (RunEvaluation::flat_metric_names, or this row's own), with the closest column's name.
void check_metric_names(const std::vector<Requirement>& requirements,
                        const nlohmann::ordered_json& flat_metrics);

struct RequirementResult {
  Requirement requirement;
  std::optional<double> value;  // the metric's value; nullopt when the run has none
  bool met = false;
  /// "met: ate_rmse_m = 0.412 <= 0.5" or "NOT met: ate_rmse_m = 0.731, above 0.5 by 0.231".
  std::string describe() const;
};

std::vector<RequirementResult> check_requirements(const std::vector<Requirement>& requirements,
                                                  const nlohmann::ordered_json& flat_metrics);

}  // namespace wifislam::eval
