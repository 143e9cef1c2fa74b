#pragma once
// The evaluation plots (plot/canvas.hpp, PNG or SVG by extension). `plan` (the dataset's world's)
// is drawn as a backdrop when given; without it the plots show the paths alone.

#include <filesystem>

#include "eval/run_evaluation.hpp"
#include "plot/canvas.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::eval {

/// The canvas of the plan plots: the plan's bounds (when given) and every point drawn.
plot::MetricCanvas plan_canvas(const RunEvaluation& ev, const sim::world::FloorPlan* plan);

/// Ground truth and the aligned estimate over the floor plan, with the detected loop closures
/// drawn between their keyframes' ground-truth positions: green correct, red false (a long red
/// edge is a closure between two different places).
void plot_trajectory(const std::filesystem::path& path, const RunEvaluation& ev,
                     const sim::world::FloorPlan* plan);

/// ATE (after alignment) along the ground-truth path length, with its RMSE.
void plot_error_along_path(const std::filesystem::path& path, const RunEvaluation& ev);

/// Keyframes at their ground-truth positions coloured by Wi-Fi cluster (founders ringed and
/// labelled with the cluster id) over the floor plan.
void plot_wifi_clusters(const std::filesystem::path& path, const RunEvaluation& ev,
                        const sim::world::FloorPlan* plan);

}  // namespace wifislam::eval
