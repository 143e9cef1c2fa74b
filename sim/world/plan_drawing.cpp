#include "sim/world/plan_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace wifislam::sim::world {

namespace {

using plot::Colour;
using plot::MetricCanvas;

Colour material_colour(radio_model::WallMaterial m) {
  switch (m) {
    case radio_model::WallMaterial::kPlasterboard:
      return {0.55, 0.60, 0.68};
    case radio_model::WallMaterial::kBrick:
      return {0.72, 0.30, 0.20};
    case radio_model::WallMaterial::kConcrete:
      return {0.35, 0.35, 0.35};
    case radio_model::WallMaterial::kGlass:
      return {0.30, 0.70, 0.85};
    case radio_model::WallMaterial::kWoodDoor:
      return {0.55, 0.36, 0.12};
  }
  return {0, 0, 0};
}

constexpr double kLegendPx = 190;
constexpr Colour kFreeSpace{0.96, 0.94, 0.89};
constexpr Colour kRoom{0.90, 0.93, 0.97};
constexpr Colour kOpenDoor{0.15, 0.65, 0.25};
constexpr Colour kRoute{0.10, 0.30, 0.85};
constexpr Colour kLight{0.98, 0.85, 0.15};
constexpr Colour kAp{0.85, 0.10, 0.10};

void draw_walls(cairo_t* cr, const MetricCanvas& c, const FloorPlan& plan, double thickness_m) {
  plot::fill_regions(cr, plan.walls, plot::through(c), {0.25, 0.25, 0.25});
  // Each face paints one wall thickness behind it in its wall's material: both faces of a wall
  // carry the same material, and walls thicker than the nominal one get covered from both sides.
  for (const WallFace2& f : plan.wall_faces) {
    const Eigen::Vector2d d = (f.b_m - f.a_m).normalized();
    const Eigen::Vector2d right(d.y(), -d.x());
    const double depth = f.door_index >= 0 ? 0.5 * thickness_m : thickness_m;
    plot::ring_path(cr, {f.a_m, f.b_m, f.b_m + depth * right, f.a_m + depth * right},
                    plot::through(c));
    plot::set_colour(cr, material_colour(f.material));
    cairo_fill(cr);
  }
}

void draw_doors(cairo_t* cr, const MetricCanvas& c, const FloorPlan& plan) {
  for (const Door& d : plan.doors) {
    const Eigen::Vector2d u = d.along_wall, n(-u.y(), u.x());
    const double hw = 0.5 * d.width_m, ht = 0.5 * d.wall_thickness_m;
    if (d.open && d.room_index < 0) {
      // An opening between two walkable spaces (imported plans have them): no room to swing a
      // leaf into, so its two edges in green.
      plot::set_colour(cr, kOpenDoor);
      plot::draw_segment(cr, c, d.center_m - hw * u - ht * n, d.center_m - hw * u + ht * n, 1.5);
      plot::draw_segment(cr, c, d.center_m + hw * u - ht * n, d.center_m + hw * u + ht * n, 1.5);
    } else if (d.open) {
      // Opening outlined in green, with the leaf swung into the room.
      plot::set_colour(cr, kOpenDoor);
      const Eigen::Vector2d room_dir =
          (plan.rooms[d.room_index].polygon_m[0] - d.center_m).dot(n) > 0 ? n : Eigen::Vector2d(-n);
      const Eigen::Vector2d hinge = d.center_m - hw * u + ht * room_dir;
      plot::draw_segment(cr, c, hinge, hinge + d.width_m * room_dir, std::max(1.5, 0.05 * c.ppm()));
      plot::draw_segment(cr, c, d.center_m - hw * u - ht * room_dir,
                         d.center_m + hw * u - ht * room_dir, 1.0);
    } else {
      // The leaf already shows in the door material; a thin dark line marks its edges.
      plot::set_colour(cr, {0.2, 0.1, 0.0});
      plot::draw_segment(cr, c, d.center_m - hw * u - ht * n, d.center_m - hw * u + ht * n, 1.0);
      plot::draw_segment(cr, c, d.center_m + hw * u - ht * n, d.center_m + hw * u + ht * n, 1.0);
    }
  }
}

void draw_route(cairo_t* cr, const MetricCanvas& c, const RoutePath& route) {
  if (route.points_m.size() < 2) return;
  plot::set_colour(cr, kRoute, 0.85);
  plot::draw_polyline(cr, c, route.points_m, 2.0);
  // Arrows every 5 m of travel.
  const double spacing_m = 5.0;
  double next = 2.5;
  for (std::size_t i = 0; i < route.points_m.size(); ++i) {
    if (route.arc_length_m[i] < next) continue;
    next += spacing_m;
    const Eigen::Vector2d p = c.px(route.points_m[i]);
    const double h = route.heading_rad[i];
    const Eigen::Vector2d f(std::cos(h), -std::sin(h)), s(std::sin(h), std::cos(h));
    const double size = 7.0;
    plot::ring_path(cr,
                    {p + size * f, p - size * f + 0.7 * size * s, p - size * f - 0.7 * size * s},
                    plot::as_is);
    cairo_fill(cr);
  }
  const Eigen::Vector2d start = c.px(route.points_m.front());
  cairo_arc(cr, start.x(), start.y(), 7.0, 0, 2 * M_PI);
  plot::set_colour(cr, {0.1, 0.7, 0.2});
  cairo_fill_preserve(cr);
  plot::set_colour(cr, {1, 1, 1});
  cairo_set_line_width(cr, 2.0);
  cairo_stroke(cr);
}

void draw_lights(cairo_t* cr, const MetricCanvas& c, const FloorPlan& plan) {
  for (const CeilingLight& l : plan.lights) {
    const Eigen::Vector2d a = c.px(l.center_m.head<2>() - 0.5 * l.size_m);
    const Eigen::Vector2d b = c.px(l.center_m.head<2>() + 0.5 * l.size_m);
    cairo_rectangle(cr, a.x(), b.y(), b.x() - a.x(), a.y() - b.y());
    plot::set_colour(cr, kLight);
    cairo_fill_preserve(cr);
    plot::set_colour(cr, {0.6, 0.5, 0.0});
    cairo_set_line_width(cr, 0.8);
    cairo_stroke(cr);
  }
}

void draw_access_points(cairo_t* cr, const MetricCanvas& c,
                        const std::vector<Eigen::Vector3d>& access_points_m) {
  for (const auto& ap : access_points_m) {
    const Eigen::Vector2d p = c.px(ap.head<2>());
    cairo_arc(cr, p.x(), p.y(), 5.0, 0, 2 * M_PI);
    plot::set_colour(cr, kAp);
    cairo_fill_preserve(cr);
    plot::set_colour(cr, {1, 1, 1});
    cairo_set_line_width(cr, 1.5);
    cairo_stroke(cr);
  }
}

void draw_legend(cairo_t* cr, const FloorPlan& plan, const PlanDrawingOptions& options, double x,
                 double y) {
  std::set<radio_model::WallMaterial> materials;
  for (const WallFace2& f : plan.wall_faces) materials.insert(f.material);
  plot::set_colour(cr, {0, 0, 0});
  plot::draw_text(cr, x, y, "walls", 14, true);
  y += 22;
  for (radio_model::WallMaterial m : materials)
    y = plot::legend_box(
        cr, x, y, material_colour(m),
        m == radio_model::WallMaterial::kWoodDoor ? "closed door (wood)" : to_string(m));
  y += 8;
  plot::set_colour(cr, {0, 0, 0});
  plot::draw_text(cr, x, y, "plan", 14, true);
  y += 22;
  y = plot::legend_box(cr, x, y, kFreeSpace, "corridor / hall");
  if (!plan.rooms.empty()) y = plot::legend_box(cr, x, y, kRoom, "room");
  if (std::any_of(plan.doors.begin(), plan.doors.end(), [](const Door& d) { return d.open; }))
    y = plot::legend_box(cr, x, y, kOpenDoor, "open door");
  if (options.draw_lights && !plan.lights.empty())
    y = plot::legend_box(cr, x, y, kLight, "ceiling light");
  if (!options.access_points_m.empty()) y = plot::legend_box(cr, x, y, kAp, "access point");
  if (options.draw_route) {
    y = plot::legend_box(cr, x, y, kRoute, "route (arrows: direction)");
    plot::legend_box(cr, x, y, {0.1, 0.7, 0.2}, "route start");
  }
}

}  // namespace

void draw_plan_backdrop(cairo_t* cr, const plot::MetricCanvas& canvas, const FloorPlan& plan) {
  plot::fill_regions(cr, plan.free_space, plot::through(canvas), {0.96, 0.95, 0.92});
  for (const Room& r : plan.rooms) {
    plot::ring_path(cr, r.polygon_m, plot::through(canvas));
    plot::set_colour(cr, {0.92, 0.93, 0.95});
    cairo_fill(cr);
  }
  plot::fill_regions(cr, plan.walls, plot::through(canvas), {0.45, 0.45, 0.45});
}

void draw_floor_plan(const World& world, const std::filesystem::path& path,
                     const PlanDrawingOptions& options) {
  const FloorPlan& plan = world.plan;
  Eigen::Vector2d lo = plan.bounds_min_m, hi = plan.bounds_max_m;
  for (const auto& ap : options.access_points_m)
    lo = lo.cwiseMin(ap.head<2>()), hi = hi.cwiseMax(ap.head<2>());
  lo -= Eigen::Vector2d::Constant(0.5);
  hi += Eigen::Vector2d::Constant(0.5);
  const Eigen::Vector2d extent = (hi - lo).cwiseMax(1.0);
  const double ppm =
      std::clamp(options.max_plan_pixels / std::max(extent.x(), extent.y()), 4.0, 80.0);
  constexpr double kMarginPx = MetricCanvas::kMarginPx, kTitlePx = MetricCanvas::kTitlePx;
  const int width = static_cast<int>(std::ceil(2 * kMarginPx + extent.x() * ppm + kLegendPx));
  const int height = static_cast<int>(std::ceil(kTitlePx + extent.y() * ppm + 50 + kMarginPx));
  const MetricCanvas canvas = MetricCanvas::exact(lo, hi, ppm);

  plot::write_figure(path, width, height, [&](cairo_t* cr) {
    plot::fill_regions(cr, plan.free_space, plot::through(canvas), kFreeSpace);
    for (const Room& r : plan.rooms) {
      plot::ring_path(cr, r.polygon_m, plot::through(canvas));
      plot::set_colour(cr, kRoom);
      cairo_fill(cr);
    }
    draw_walls(cr, canvas, plan, plan.wall_thickness_m);
    draw_doors(cr, canvas, plan);
    if (options.draw_lights) draw_lights(cr, canvas, plan);
    if (options.draw_route) draw_route(cr, canvas, world.route);
    draw_access_points(cr, canvas, options.access_points_m);

    plot::set_colour(cr, {0, 0, 0});
    plot::draw_text(cr, kMarginPx, 28, options.title, 20, true);
    plot::draw_scale_bar(cr, kMarginPx, kTitlePx + extent.y() * ppm + 30, ppm, extent.x(),
                         {.longest_m = 50, .end_ticks = true});
    draw_legend(cr, plan, options, kMarginPx * 2 + extent.x() * ppm, kTitlePx + 10);
  });
}

}  // namespace wifislam::sim::world
