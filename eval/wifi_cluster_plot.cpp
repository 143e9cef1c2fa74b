#include <fmt/format.h>

#include "eval/plots.hpp"
#include "plot/canvas.hpp"
#include "sim/world/plan_drawing.hpp"

namespace wifislam::eval {

void plot_wifi_clusters(const std::filesystem::path& path, const RunEvaluation& ev,
                        const sim::world::FloorPlan* plan) {
  const plot::MetricCanvas canvas = plan_canvas(ev, plan);
  plot::write_figure(path, canvas.width_px(), canvas.height_px(), [&](cairo_t* cr) {
    if (plan) sim::world::draw_plan_backdrop(cr, canvas, *plan);
    std::vector<Eigen::Vector2d> gt;
    for (const PathSample& s : ev.path) gt.push_back(s.ground_truth_m.head<2>());
    plot::set_colour(cr, {0.6, 0.6, 0.6}, 0.8);
    plot::draw_polyline(cr, canvas, gt, 1.0);
    const auto position = [&](std::int64_t k) {
      return canvas.px(
          ev.keyframe_truth[static_cast<std::size_t>(k)].ground_truth.translation().head<2>());
    };
    std::vector<char> clustered(ev.keyframe_truth.size(), 0);
    for (const WifiCluster& c : ev.wifi_cluster_list) {
      plot::set_colour(cr, plot::category_colour(c.id));
      for (std::int64_t k : c.keyframes) {
        const Eigen::Vector2d p = position(k);
        clustered[static_cast<std::size_t>(k)] = 1;
        cairo_arc(cr, p.x(), p.y(), 4.0, 0, 2 * M_PI);
        cairo_fill(cr);
      }
    }
    // Keyframes without a cluster (no Wi-Fi signature yet): small grey dots.
    plot::set_colour(cr, {0.5, 0.5, 0.5});
    for (std::size_t k = 0; k < clustered.size(); ++k) {
      if (clustered[k]) continue;
      const Eigen::Vector2d p = position(static_cast<std::int64_t>(k));
      cairo_arc(cr, p.x(), p.y(), 2.0, 0, 2 * M_PI);
      cairo_fill(cr);
    }
    for (const WifiCluster& c : ev.wifi_cluster_list) {
      if (c.founder_keyframe < 0 ||
          c.founder_keyframe >= static_cast<std::int64_t>(ev.keyframe_truth.size())) {
        continue;
      }
      const Eigen::Vector2d p = position(c.founder_keyframe);
      plot::set_colour(cr, {0, 0, 0});
      cairo_set_line_width(cr, 1.5);
      cairo_arc(cr, p.x(), p.y(), 7.0, 0, 2 * M_PI);
      cairo_stroke(cr);
      plot::draw_text(cr, p.x() + 8, p.y() - 8, std::to_string(c.id), 12, true);
    }
    plot::set_colour(cr, {0, 0, 0});
    plot::draw_text(
        cr, plot::MetricCanvas::kMarginPx, 28,
        fmt::format("Wi-Fi clusters: {} clusters, {} keyframes", ev.wifi_clusters, ev.keyframes),
        18, true);
    const double x = canvas.plan_right_px() + plot::MetricCanvas::kMarginPx;
    double y = plot::MetricCanvas::kTitlePx + 14;
    std::size_t shown = 0;
    for (const WifiCluster& c : ev.wifi_cluster_list) {
      if (++shown > 24) {
        plot::draw_text(cr, x, y, fmt::format("... {} more", ev.wifi_cluster_list.size() - 24), 13);
        y += 20;
        break;
      }
      y = plot::legend_dot(cr, x, y, plot::category_colour(c.id),
                           fmt::format("cluster {} ({} keyframes)", c.id, c.keyframes.size()));
    }
    y = plot::legend_dot(cr, x, y, {0.5, 0.5, 0.5}, "no cluster");
    plot::set_colour(cr, {0.3, 0.3, 0.3});
    plot::draw_text(cr, x, y + 6, "ringed: founder keyframe", 11);
    plot::draw_scale_bar(cr, canvas);
  });
}

}  // namespace wifislam::eval
