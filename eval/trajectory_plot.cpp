#include <fmt/format.h>

#include "eval/plots.hpp"
#include "plot/canvas.hpp"
#include "sim/world/plan_drawing.hpp"

namespace wifislam::eval {

namespace {
constexpr plot::Colour kGroundTruth{0.15, 0.15, 0.15};
constexpr plot::Colour kEstimate{0.10, 0.35, 0.90};
constexpr plot::Colour kCorrect{0.10, 0.65, 0.20};
constexpr plot::Colour kImprecise{0.95, 0.60, 0.05};
constexpr plot::Colour kFalse{0.90, 0.10, 0.10};

plot::Colour verdict_colour(LoopClosureVerdict v) {
  switch (v) {
    case LoopClosureVerdict::kCorrect:
      return kCorrect;
    case LoopClosureVerdict::kRightPlaceImprecise:
      return kImprecise;
    case LoopClosureVerdict::kWrongPlace:
      return kFalse;
  }
  return kFalse;
}
}  // namespace

plot::MetricCanvas plan_canvas(const RunEvaluation& ev, const sim::world::FloorPlan* plan) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = Eigen::Vector2d::Constant(-1e300);
  auto include = [&](const Eigen::Vector2d& p) { lo = lo.cwiseMin(p), hi = hi.cwiseMax(p); };
  if (plan) include(plan->bounds_min_m), include(plan->bounds_max_m);
  for (const PathSample& s : ev.path) {
    include(s.ground_truth_m.head<2>());
    include(s.estimated_aligned_m.head<2>());
  }
  for (const KeyframeTruth& k : ev.keyframe_truth) include(k.ground_truth.translation().head<2>());
  if (lo.x() > hi.x()) lo = hi = Eigen::Vector2d::Zero();
  return plot::MetricCanvas(lo, hi, 1200);
}

void plot_trajectory(const std::filesystem::path& path, const RunEvaluation& ev,
                     const sim::world::FloorPlan* plan) {
  const plot::MetricCanvas canvas = plan_canvas(ev, plan);
  plot::write_figure(path, canvas.width_px(), canvas.height_px(), [&](cairo_t* cr) {
    if (plan) sim::world::draw_plan_backdrop(cr, canvas, *plan);
    std::vector<Eigen::Vector2d> gt, est;
    for (const PathSample& s : ev.path) {
      gt.push_back(s.ground_truth_m.head<2>());
      est.push_back(s.estimated_aligned_m.head<2>());
    }
    plot::set_colour(cr, kGroundTruth, 0.8);
    plot::draw_polyline(cr, canvas, gt, 2.0);
    plot::set_colour(cr, kEstimate, 0.85);
    plot::draw_polyline(cr, canvas, est, 2.0);
    std::int64_t correct = 0, imprecise = 0, wrong = 0;
    for (const ScoredLoopClosure& c : ev.loop_closure_score.closures) {
      const auto& kf = ev.keyframe_truth;
      const Eigen::Vector2d a = canvas.px(
          kf[static_cast<std::size_t>(c.edge.from_keyframe)].ground_truth.translation().head<2>());
      const Eigen::Vector2d b = canvas.px(
          kf[static_cast<std::size_t>(c.edge.to_keyframe)].ground_truth.translation().head<2>());
      plot::set_colour(cr, verdict_colour(c.verdict), 0.9);
      cairo_set_line_width(cr, c.correct() ? 2.0 : 2.5);
      if (c.edge.pruned) {
        const double dash[] = {6.0, 4.0};
        cairo_set_dash(cr, dash, 2, 0);
      }
      cairo_move_to(cr, a.x(), a.y());
      cairo_line_to(cr, b.x(), b.y());
      cairo_stroke(cr);
      cairo_set_dash(cr, nullptr, 0, 0);
      for (const Eigen::Vector2d& p : {a, b}) {
        cairo_arc(cr, p.x(), p.y(), 3.0, 0, 2 * M_PI);
        cairo_fill(cr);
      }
      (c.correct()                                    ? correct
       : c.verdict == LoopClosureVerdict::kWrongPlace ? wrong
                                                      : imprecise) += 1;
    }
    if (!gt.empty()) {
      const Eigen::Vector2d start = canvas.px(gt.front());
      plot::set_colour(cr, kCorrect);
      cairo_arc(cr, start.x(), start.y(), 6.0, 0, 2 * M_PI);
      cairo_fill(cr);
    }
    plot::set_colour(cr, {0, 0, 0});
    plot::draw_text(
        cr, plot::MetricCanvas::kMarginPx, 28,
        ev.loop_closures_available
            ? fmt::format("Trajectory: ATE RMSE {:.3f} m, {} loop closure{} ({} wrong place)",
                          ev.ate_rmse_m, ev.loop_closures_detected,
                          ev.loop_closures_detected == 1 ? "" : "s", ev.false_positives)
            : fmt::format("Trajectory: ATE RMSE {:.3f} m (loop closures not available)",
                          ev.ate_rmse_m),
        18, true);
    const double x = canvas.plan_right_px() + plot::MetricCanvas::kMarginPx;
    double y = plot::MetricCanvas::kTitlePx + 14;
    y = plot::legend_line(cr, x, y, kGroundTruth, 2.0, "ground truth");
    y = plot::legend_line(cr, x, y, kEstimate, 2.0,
                          ev.options.align == AlignmentMode::kSim3  ? "estimate (Sim(3)-aligned)"
                          : ev.options.align == AlignmentMode::kSe3 ? "estimate (aligned)"
                                                                    : "estimate (not aligned)");
    if (ev.loop_closures_available) {
      y = plot::legend_line(cr, x, y, kCorrect, 2.0,
                            fmt::format("correct loop closure ({})", correct));
      y = plot::legend_line(cr, x, y, kImprecise, 2.5,
                            fmt::format("right place, imprecise ({})", imprecise));
      y = plot::legend_line(cr, x, y, kFalse, 2.5, fmt::format("wrong place ({})", wrong));
    }
    y = plot::legend_dot(cr, x, y, kCorrect, "start");
    plot::set_colour(cr, {0.3, 0.3, 0.3});
    plot::draw_text(cr, x, y + 6, "closures drawn between the", 11);
    plot::draw_text(cr, x, y + 20, "keyframes' true positions", 11);
    plot::draw_text(cr, x, y + 34, "(dashed: pruned after the run)", 11);
    plot::draw_scale_bar(cr, canvas);
  });
}

}  // namespace wifislam::eval
