#pragma once
// Drawing helpers shared by the evaluation plots (cairo): a PNG or SVG surface chosen by the
// file extension, a metric canvas mapping world metres to pixels, the floor plan as a backdrop,
// and text/legend helpers. The plan backdrop draws only what a trajectory plot needs (free space,
// rooms, wall solids): sim/world's draw_floor_plan writes a finished file with its own legend and
// route, which cannot take our layers on top.

#include <cairo.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sim/world/world_types.hpp"

namespace wifislam::eval {

struct Colour {
  double r = 0, g = 0, b = 0;
};

/// Creates a `width` x `height` surface (SVG when `path` ends in ".svg", PNG otherwise), calls
/// `draw`, and writes the file. Throws IoError when it cannot be written.
void render_figure(const std::filesystem::path& path, int width_px, int height_px,
                   const std::function<void(cairo_t*)>& draw);

/// World metres (x east, y north) -> pixels, with the plan's y axis pointing up.
class MetricCanvas {
 public:
  static constexpr double kMarginPx = 30, kTitlePx = 44, kLegendPx = 240, kFooterPx = 50;
  /// Fits [lo, hi] (metres) so the longer side is about `max_plan_px` pixels.
  MetricCanvas(Eigen::Vector2d lo_m, Eigen::Vector2d hi_m, double max_plan_px);

  Eigen::Vector2d px(const Eigen::Vector2d& p_m) const;
  double ppm() const { return ppm_; }
  int width_px() const;
  int height_px() const;
  double plan_right_px() const { return kMarginPx + (hi_.x() - lo_.x()) * ppm_; }
  double plan_bottom_px() const { return kTitlePx + (hi_.y() - lo_.y()) * ppm_; }
  double plan_width_m() const { return hi_.x() - lo_.x(); }

 private:
  Eigen::Vector2d lo_, hi_;
  double ppm_ = 10;
};

void set_colour(cairo_t* cr, const Colour& c, double alpha = 1.0);
void draw_text(cairo_t* cr, double x, double y, const std::string& text, double size,
               bool bold = false);
void draw_polyline(cairo_t* cr, const MetricCanvas& canvas,
                   const std::vector<Eigen::Vector2d>& points_m, double width_px);
/// Free space, rooms and wall solids of the plan.
void draw_plan_backdrop(cairo_t* cr, const MetricCanvas& canvas, const sim::FloorPlan& plan);
/// A scale bar under the plan.
void draw_scale_bar(cairo_t* cr, const MetricCanvas& canvas);

/// Legend entries stacked from (x, y): a line or dot swatch and a label. Returns the next y.
double legend_line(cairo_t* cr, double x, double y, const Colour& c, double width_px,
                   const std::string& label);
double legend_dot(cairo_t* cr, double x, double y, const Colour& c, const std::string& label);

/// Distinct colours for categories (Wi-Fi clusters): a fixed palette, then golden-angle hues.
Colour category_colour(std::int64_t index);

}  // namespace wifislam::eval
