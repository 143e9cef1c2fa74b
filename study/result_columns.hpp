#pragma once
// The columns a study writes for a case (result_store.hpp), each named once with where its value
// comes from: the radio level's from the route's signature resolution (radio_resolution.hpp), the
// SLAM level's from each run's evaluation (eval/run_evaluation.hpp, which defines the metrics).
// The tables' column order is the database schema; adding a column is one line here.

#include <functional>
#include <string>
#include <vector>

#include "eval/run_evaluation.hpp"
#include "study/radio_resolution.hpp"
#include "study/result_store.hpp"

namespace wifislam::study {

template <class Source>
struct StudyColumn {
  const char* name;
  std::function<SqlValue(const Source&)> value;
};

/// results columns of a radio-level case.
const std::vector<StudyColumn<RadioResolution>>& radio_metric_columns();
/// results and timing (wall-clock seconds) columns of a SLAM-level case's run.
const std::vector<StudyColumn<eval::RunEvaluation>>& slam_metric_columns();
const std::vector<StudyColumn<eval::RunEvaluation>>& slam_timing_columns();

/// The loop-closure time the paper's tables give, measured as the front end's original system
/// times it (seconds):
///   rtabmap   likelihood + posterior (thread CPU) + the loop hypothesis' verification, the
///             categories Rtabmap::process times for loop closure detection;
///   orbslam   LoopClosing: the loop query (DetectLoop, SearchByBoW) + the Sim3 verifications +
///             the pose-graph optimisations (CorrectLoop's essential graph; the pipeline optimises
///             after loop closures and once at the end);
///   others    the module bounding acts on (RGBD-SLAM's "affected modules"): candidate selection +
///             the long-term verifications + optimisation.
double paper_loop_closure_s(const eval::RunEvaluation& e);

/// The values of `columns` for one source, in column order.
template <class Source>
std::vector<ResultColumn> column_values(const std::vector<StudyColumn<Source>>& columns,
                                        const Source& source) {
  std::vector<ResultColumn> out;
  out.reserve(columns.size());
  for (const StudyColumn<Source>& c : columns) out.push_back({c.name, c.value(source)});
  return out;
}

template <class Source>
std::vector<std::string> column_names(const std::vector<StudyColumn<Source>>& columns) {
  std::vector<std::string> out;
  for (const StudyColumn<Source>& c : columns) out.emplace_back(c.name);
  return out;
}

}  // namespace wifislam::study
