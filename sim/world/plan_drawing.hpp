#pragma once
// A picture of the floor plan on the shared canvas (plot/canvas.hpp): free space, rooms, walls
// coloured by material with a legend, doors (open / closed), ceiling lights, access points, the
// route with direction arrows and its start, a scale bar in metres and a title; and the plan as a
// backdrop under other figures (the evaluation's trajectories, the placement figure).

#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "plot/canvas.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::world {

struct PlanDrawingOptions {
  std::string title;
  std::vector<Eigen::Vector3d> access_points_m;  // drawn when not empty
  bool draw_route = true;
  bool draw_lights = true;
  double max_plan_pixels = 1400;  // longest side of the plan area; sets the scale
};

/// Free space, rooms and wall solids of the plan, in muted colours, under a figure's own layers.
void draw_plan_backdrop(cairo_t* cr, const plot::MetricCanvas& canvas, const FloorPlan& plan);

/// Writes a PNG, or an SVG when `path` ends in ".svg". The file appears atomically (written to
/// `<path>.partial`, then renamed). Throws IoError when it cannot be written.
void draw_floor_plan(const World& world, const std::filesystem::path& path,
                     const PlanDrawingOptions& options = {});

}  // namespace wifislam::sim::world
