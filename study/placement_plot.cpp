// Figures of `wifislam study place` (greedy_placement.hpp): the chosen positions over the plan,
// and the resolution after each addition, greedy against random.
#include <cmath>
#include <functional>
#include <limits>

#include <fmt/format.h>

#include "plot/canvas.hpp"
#include "plot/line_chart.hpp"
#include "sim/world/plan_drawing.hpp"
#include "study/greedy_placement.hpp"

namespace wifislam::study {

namespace {

namespace fs = std::filesystem;

void draw_positions(const fs::path& path, const PlacementResult& result,
                    const std::string& scene_name) {
  Eigen::Vector2d lo = result.plan.bounds_min_m, hi = result.plan.bounds_max_m;
  for (const Eigen::Vector3d& c : result.candidates) {
    lo = lo.cwiseMin(c.head<2>());
    hi = hi.cwiseMax(c.head<2>());
  }
  const plot::MetricCanvas canvas(lo, hi, 900);
  plot::write_figure(path, canvas.width_px(), canvas.height_px(), [&](cairo_t* cr) {
    sim::world::draw_plan_backdrop(cr, canvas, result.plan);
    const plot::Colour candidate{0.70, 0.70, 0.70}, pause{0.12, 0.47, 0.71},
        chosen{0.84, 0.15, 0.16};
    plot::set_colour(cr, candidate);
    for (const Eigen::Vector3d& c : result.candidates) {
      const Eigen::Vector2d p = canvas.px(c.head<2>());
      cairo_arc(cr, p.x(), p.y(), 2.0, 0, 2 * M_PI);
      cairo_fill(cr);
    }
    plot::set_colour(cr, pause, 0.8);
    for (const Eigen::Vector2d& q : result.pause_positions_m) {
      const Eigen::Vector2d p = canvas.px(q);
      cairo_rectangle(cr, p.x() - 2.5, p.y() - 2.5, 5, 5);
      cairo_fill(cr);
    }
    for (const PlacementStep& s : result.steps) {
      const Eigen::Vector3d& c = result.candidates[static_cast<std::size_t>(s.candidate)];
      const Eigen::Vector2d p = canvas.px(c.head<2>());
      plot::set_colour(cr, chosen);
      cairo_arc(cr, p.x(), p.y(), 7.0, 0, 2 * M_PI);
      cairo_fill(cr);
      plot::set_colour(cr, {1, 1, 1});
      const std::string label = std::to_string(s.count);
      plot::draw_text(cr, p.x() - 3.5 * static_cast<double>(label.size()), p.y() + 4, label, 10,
                      true);
    }
    plot::set_colour(cr, {0, 0, 0});
    plot::draw_text(
        cr, plot::MetricCanvas::kMarginPx, 22,
        fmt::format("{}: {} access points placed greedily", scene_name, result.steps.size()), 15,
        true);
    plot::draw_text(cr, plot::MetricCanvas::kMarginPx, 38,
                    "numbered in the order chosen, each the candidate that best resolved the "
                    "route's pauses",
                    11);
    plot::draw_scale_bar(cr, canvas);
    double y = plot::MetricCanvas::kTitlePx + 14;
    const double x = canvas.plan_right_px() + 20;
    y = plot::legend_dot(cr, x, y, chosen, "chosen access point");
    y = plot::legend_dot(cr, x, y, candidate,
                         fmt::format("candidate ({})", result.candidates.size()));
    y = plot::legend_dot(cr, x, y, pause,
                         fmt::format("pause (scan spot, {})", result.pause_positions_m.size()));
  });
}

/// One quantity after each addition, greedy (solid) against the random median (dashed).
void draw_curve(const fs::path& path, const std::string& title, const std::string& subtitle,
                const std::string& y_label, const PlacementResult& result,
                const std::function<double(const PlacementStep&, bool random)>& value) {
  plot::LineChart chart;
  chart.title = title;
  chart.subtitle = subtitle;
  chart.x_label = "access points";
  chart.y_label = y_label;
  plot::ChartSeries greedy{"greedy", plot::category_colour(3), false, {}};
  plot::ChartSeries random{"random (median)", plot::category_colour(0), true, {}};
  for (const PlacementStep& s : result.steps) {
    const double g = value(s, false), r = value(s, true);
    greedy.points.push_back({static_cast<double>(s.count), g, g, g});
    random.points.push_back({static_cast<double>(s.count), r, r, r});
  }
  chart.series = {greedy, random};
  plot::draw_line_chart(path, chart);
}

}  // namespace

std::vector<fs::path> plot_placement(const PlacementResult& result, const std::string& scene_name,
                                     const fs::path& folder) {
  std::vector<fs::path> files;
  for (const char* extension : {".png", ".svg"}) {
    files.push_back(folder / (std::string("placement") + extension));
    draw_positions(files.back(), result, scene_name);
    const double none = std::numeric_limits<double>::quiet_NaN();
    files.push_back(folder / (std::string("error") + extension));
    draw_curve(
        files.back(), fmt::format("{}: placement error against access points placed", scene_name),
        fmt::format("(1 - pairs < 4 m similar) + pairs > 12 m similar, greedy against "
                    "random placements of the same candidates; the scene's own {} APs: {:.3f}",
                    result.scene_access_points, placement_error(result.scene_own)),
        "placement error (lower is better)", result, [](const PlacementStep& s, bool random) {
          return random ? s.random_error : s.greedy_error;
        });
    files.push_back(folder / (std::string("resolution") + extension));
    draw_curve(files.back(),
               fmt::format("{}: signature resolution against access points placed", scene_name),
               fmt::format("greedy against random placements of the same candidates (median); the "
                           "scene's own {} APs: {}",
                           result.scene_access_points,
                           result.scene_own.resolution_m
                               ? fmt::format("{:.1f} m", *result.scene_own.resolution_m)
                               : std::string("none")),
               "signature resolution [m]", result, [none](const PlacementStep& s, bool random) {
                 return (random ? s.random_resolution_m : s.greedy.resolution_m).value_or(none);
               });
  }
  return files;
}

}  // namespace wifislam::study
