#pragma once
// The one drawing canvas of the project (cairo), shared by every picture it makes: the floor plan
// (sim/world/plan_drawing), the radio map (radio_model/radio_map), the evaluation plots (eval/) and
// the study and benchmark charts (line_chart.hpp). It sits below the simulator and knows no world
// type: points are Eigen vectors in metres (x east, y north), rings are lists of them.
//
//   write_figure     a PNG or SVG file (by extension), white background, written atomically
//   MetricCanvas     metres -> pixels for a plan-shaped figure (title above, legend right)
//   paths            rings and regions with holes as cairo paths, through any point mapping
//   marks            text, polylines, scale bar, legend rows

#include <cairo.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace wifislam::plot {

struct Colour {
  double r = 0, g = 0, b = 0;
};

void set_colour(cairo_t* cr, const Colour& c, double alpha = 1.0);

/// Distinct colours for categories (Wi-Fi clusters, chart lines): a fixed palette, then
/// golden-angle hues.
Colour category_colour(std::int64_t index);

/// Viridis (matplotlib's perceptually uniform map) at t in [0, 1], sampled at five points.
Colour viridis(double t);

// --- Files ----------------------------------------------------------------------------------

/// PNG pixels: with an alpha channel (ARGB32, the default) or opaque (RGB24).
enum class PixelFormat { kArgb32, kRgb24 };

/// Creates a `width` x `height` surface (SVG when `path` ends in ".svg", PNG otherwise), paints
/// it white, calls `draw`, and writes the file atomically (`<path>.partial`, then renamed).
/// Throws IoError when it cannot be created or written, InvalidInputError when `path` is a folder,
/// device or pipe (core/output_folder.hpp's check_file_replaceable).
void write_figure(const std::filesystem::path& path, int width_px, int height_px,
                  const std::function<void(cairo_t*)>& draw,
                  PixelFormat format = PixelFormat::kArgb32);

// --- Plan-shaped figures ----------------------------------------------------------------------

/// World metres (x east, y north) -> pixels, with the plan's y axis pointing up: the plan area
/// starts kMarginPx from the left and kTitlePx from the top; the legend column and the footer
/// (scale bar) are the caller's layout.
class MetricCanvas {
 public:
  static constexpr double kMarginPx = 30, kTitlePx = 44, kLegendPx = 240, kFooterPx = 50;

  /// The plot layout: [lo, hi] padded by 0.5 m, at least 1 m a side, the longer side about
  /// `max_plan_px` pixels (2 to 120 px a metre).
  MetricCanvas(Eigen::Vector2d lo_m, Eigen::Vector2d hi_m, double max_plan_px);
  /// A given mapping: `lo_m` at the plan area's left, `hi_m.y()` at its top, `ppm` pixels a metre.
  static MetricCanvas exact(const Eigen::Vector2d& lo_m, const Eigen::Vector2d& hi_m, double ppm);

  Eigen::Vector2d px(const Eigen::Vector2d& p_m) const;
  double ppm() const { return ppm_; }
  /// Figure size for the plot layout: plan, legend column (kLegendPx), footer (kFooterPx), at
  /// least 360 px high.
  int width_px() const;
  int height_px() const;
  double plan_right_px() const { return kMarginPx + (hi_.x() - lo_.x()) * ppm_; }
  double plan_bottom_px() const { return kTitlePx + (hi_.y() - lo_.y()) * ppm_; }
  double plan_width_m() const { return hi_.x() - lo_.x(); }

 private:
  MetricCanvas() = default;
  Eigen::Vector2d lo_, hi_;
  double ppm_ = 10;
};

// --- Paths --------------------------------------------------------------------------------------

/// A closed ring as a cairo sub-path, each point through `to_px` (a canvas, or the identity when
/// the cairo matrix already maps metres).
template <class ToPx>
void ring_path(cairo_t* cr, const std::vector<Eigen::Vector2d>& ring, const ToPx& to_px) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Eigen::Vector2d q = to_px(ring[i]);
    i == 0 ? cairo_move_to(cr, q.x(), q.y()) : cairo_line_to(cr, q.x(), q.y());
  }
  if (!ring.empty()) cairo_close_path(cr);
}

/// A region (anything with `outer` and `holes` rings) as sub-paths; filled with the even-odd rule
/// the holes stay empty.
template <class Region, class ToPx>
void region_path(cairo_t* cr, const Region& region, const ToPx& to_px) {
  ring_path(cr, region.outer, to_px);
  for (const auto& hole : region.holes) ring_path(cr, hole, to_px);
}

/// Fills each region on its own (even-odd): overlapping regions do not cancel out.
template <class Regions, class ToPx>
void fill_regions(cairo_t* cr, const Regions& regions, const ToPx& to_px, const Colour& c) {
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
  for (const auto& r : regions) {
    region_path(cr, r, to_px);
    set_colour(cr, c);
    cairo_fill(cr);
  }
}

/// The identity point mapping (the cairo matrix maps metres to pixels).
inline Eigen::Vector2d as_is(const Eigen::Vector2d& p) { return p; }

/// A canvas as a point mapping for the path functions.
inline auto through(const MetricCanvas& canvas) {
  return [&canvas](const Eigen::Vector2d& p) { return canvas.px(p); };
}

// --- Marks --------------------------------------------------------------------------------------

/// Text with its baseline starting at (x, y); leaves no current point behind.
void draw_text(cairo_t* cr, double x, double y, const std::string& text, double size,
               bool bold = false);
void draw_polyline(cairo_t* cr, const MetricCanvas& canvas,
                   const std::vector<Eigen::Vector2d>& points_m, double width_px);
/// A straight segment between two points in metres.
void draw_segment(cairo_t* cr, const MetricCanvas& canvas, const Eigen::Vector2d& a_m,
                  const Eigen::Vector2d& b_m, double width_px);

/// A scale bar from (x0, y): the longest of 1, 2, 5, 10, 20, 50, ... up to `longest_m` metres
/// that is at most a quarter of the plan's width, labelled; `end_ticks` marks its two ends.
struct ScaleBar {
  double longest_m = 100;
  bool end_ticks = false;
};
void draw_scale_bar(cairo_t* cr, double x0_px, double y_px, double ppm, double plan_width_m,
                    const ScaleBar& style = {});
/// The plot layout's scale bar: under the plan, 28 px below it.
void draw_scale_bar(cairo_t* cr, const MetricCanvas& canvas);

/// Legend rows stacked from (x, y): a line, a dot or a filled box, then the label. Each returns
/// the next row's y.
double legend_line(cairo_t* cr, double x, double y, const Colour& c, double width_px,
                   const std::string& label);
double legend_dot(cairo_t* cr, double x, double y, const Colour& c, const std::string& label);
double legend_box(cairo_t* cr, double x, double y, const Colour& c, const std::string& label);

}  // namespace wifislam::plot
