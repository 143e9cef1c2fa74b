#include "sim/world/plan_drawing.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <set>

#include <fmt/format.h>

#include "core/error.hpp"

namespace wifislam::sim {

namespace {

struct Rgb {
  double r, g, b;
};

Rgb material_colour(WallMaterial m) {
  switch (m) {
    case WallMaterial::kPlasterboard:
      return {0.55, 0.60, 0.68};
    case WallMaterial::kBrick:
      return {0.72, 0.30, 0.20};
    case WallMaterial::kConcrete:
      return {0.35, 0.35, 0.35};
    case WallMaterial::kGlass:
      return {0.30, 0.70, 0.85};
    case WallMaterial::kWoodDoor:
      return {0.55, 0.36, 0.12};
  }
  return {0, 0, 0};
}

constexpr double kMarginPx = 30;
constexpr double kTitlePx = 44;
constexpr double kLegendPx = 190;
constexpr Rgb kFreeSpace{0.96, 0.94, 0.89};
constexpr Rgb kRoom{0.90, 0.93, 0.97};
constexpr Rgb kOpenDoor{0.15, 0.65, 0.25};
constexpr Rgb kRoute{0.10, 0.30, 0.85};
constexpr Rgb kLight{0.98, 0.85, 0.15};
constexpr Rgb kAp{0.85, 0.10, 0.10};

class Canvas {
 public:
  Canvas(cairo_t* cr, const Eigen::Vector2d& min_m, const Eigen::Vector2d& max_m, double ppm)
      : cr_(cr), min_(min_m), max_(max_m), ppm_(ppm) {}

  Eigen::Vector2d px(const Eigen::Vector2d& p) const {
    return {kMarginPx + (p.x() - min_.x()) * ppm_, kTitlePx + (max_.y() - p.y()) * ppm_};
  }
  double ppm() const { return ppm_; }
  cairo_t* cr() const { return cr_; }
  void colour(const Rgb& c, double alpha = 1.0) const {
    cairo_set_source_rgba(cr_, c.r, c.g, c.b, alpha);
  }

  void ring_path(const Polygon2& ring) const {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Eigen::Vector2d q = px(ring[i]);
      i == 0 ? cairo_move_to(cr_, q.x(), q.y()) : cairo_line_to(cr_, q.x(), q.y());
    }
    cairo_close_path(cr_);
  }
  void fill_regions(const std::vector<PolygonWithHoles2>& regions, const Rgb& c) const {
    cairo_set_fill_rule(cr_, CAIRO_FILL_RULE_EVEN_ODD);
    for (const auto& r : regions) {
      ring_path(r.outer);
      for (const auto& h : r.holes) ring_path(h);
      colour(c);
      cairo_fill(cr_);
    }
  }
  void line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double width_px) const {
    const Eigen::Vector2d p = px(a), q = px(b);
    cairo_set_line_width(cr_, width_px);
    cairo_move_to(cr_, p.x(), p.y());
    cairo_line_to(cr_, q.x(), q.y());
    cairo_stroke(cr_);
  }
  void text(double x, double y, const std::string& s, double size, bool bold = false) const {
    cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr_, size);
    cairo_move_to(cr_, x, y);
    cairo_show_text(cr_, s.c_str());
  }

 private:
  cairo_t* cr_;
  Eigen::Vector2d min_, max_;
  double ppm_;
};

void draw_walls(const Canvas& c, const FloorPlan& plan, double thickness_m) {
  c.fill_regions(plan.walls, {0.25, 0.25, 0.25});
  // Each face paints one wall thickness behind it in its wall's material: both faces of a wall
  // carry the same material, and walls thicker than the nominal one get covered from both sides.
  for (const WallFace2& f : plan.wall_faces) {
    const Eigen::Vector2d d = (f.b_m - f.a_m).normalized();
    const Eigen::Vector2d right(d.y(), -d.x());
    const double depth = f.door_index >= 0 ? 0.5 * thickness_m : thickness_m;
    const std::array<Eigen::Vector2d, 4> q = {c.px(f.a_m), c.px(f.b_m), c.px(f.b_m + depth * right),
                                              c.px(f.a_m + depth * right)};
    cairo_move_to(c.cr(), q[0].x(), q[0].y());
    for (int i = 1; i < 4; ++i) cairo_line_to(c.cr(), q[i].x(), q[i].y());
    cairo_close_path(c.cr());
    c.colour(material_colour(f.material));
    cairo_fill(c.cr());
  }
}

void draw_doors(const Canvas& c, const FloorPlan& plan) {
  for (const Door& d : plan.doors) {
    const Eigen::Vector2d u = d.along_wall, n(-u.y(), u.x());
    const double hw = 0.5 * d.width_m, ht = 0.5 * d.wall_thickness_m;
    if (d.open) {
      // Opening outlined in green, with the leaf swung into the room.
      c.colour(kOpenDoor);
      const Eigen::Vector2d room_dir =
          (plan.rooms[d.room_index].polygon_m[0] - d.center_m).dot(n) > 0 ? n : Eigen::Vector2d(-n);
      const Eigen::Vector2d hinge = d.center_m - hw * u + ht * room_dir;
      c.line(hinge, hinge + d.width_m * room_dir, std::max(1.5, 0.05 * c.ppm()));
      c.line(d.center_m - hw * u - ht * room_dir, d.center_m + hw * u - ht * room_dir, 1.0);
    } else {
      // The leaf already shows in the door material; a thin dark line marks its edges.
      c.colour({0.2, 0.1, 0.0});
      c.line(d.center_m - hw * u - ht * n, d.center_m - hw * u + ht * n, 1.0);
      c.line(d.center_m + hw * u - ht * n, d.center_m + hw * u + ht * n, 1.0);
    }
  }
}

void draw_route(const Canvas& c, const RoutePath& route) {
  if (route.points_m.size() < 2) return;
  cairo_t* cr = c.cr();
  c.colour(kRoute, 0.85);
  cairo_set_line_width(cr, 2.0);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (std::size_t i = 0; i < route.points_m.size(); ++i) {
    const Eigen::Vector2d p = c.px(route.points_m[i]);
    i == 0 ? cairo_move_to(cr, p.x(), p.y()) : cairo_line_to(cr, p.x(), p.y());
  }
  cairo_stroke(cr);
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
    const Eigen::Vector2d tip = p + size * f, l = p - size * f + 0.7 * size * s,
                          r = p - size * f - 0.7 * size * s;
    cairo_move_to(cr, tip.x(), tip.y());
    cairo_line_to(cr, l.x(), l.y());
    cairo_line_to(cr, r.x(), r.y());
    cairo_close_path(cr);
    cairo_fill(cr);
  }
  const Eigen::Vector2d start = c.px(route.points_m.front());
  cairo_arc(cr, start.x(), start.y(), 7.0, 0, 2 * M_PI);
  c.colour({0.1, 0.7, 0.2});
  cairo_fill_preserve(cr);
  c.colour({1, 1, 1});
  cairo_set_line_width(cr, 2.0);
  cairo_stroke(cr);
}

void draw_scale_bar(const Canvas& c, double plan_width_m, double y_px) {
  double bar_m = 1;
  for (double candidate : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0})
    if (candidate <= 0.25 * plan_width_m) bar_m = candidate;
  const double x0 = kMarginPx, x1 = kMarginPx + bar_m * c.ppm();
  cairo_t* cr = c.cr();
  c.colour({0, 0, 0});
  cairo_set_line_width(cr, 3.0);
  cairo_move_to(cr, x0, y_px);
  cairo_line_to(cr, x1, y_px);
  cairo_stroke(cr);
  cairo_set_line_width(cr, 1.5);
  for (double x : {x0, x1}) {
    cairo_move_to(cr, x, y_px - 5);
    cairo_line_to(cr, x, y_px + 5);
    cairo_stroke(cr);
  }
  c.text(x1 + 8, y_px + 5, fmt::format("{:g} m", bar_m), 13);
}

void draw_legend(const Canvas& c, const FloorPlan& plan, const PlanDrawingOptions& options,
                 double x, double y) {
  std::set<WallMaterial> materials;
  for (const WallFace2& f : plan.wall_faces) materials.insert(f.material);
  cairo_t* cr = c.cr();
  c.colour({0, 0, 0});
  c.text(x, y, "walls", 14, true);
  y += 22;
  auto swatch = [&](const Rgb& col, const std::string& label) {
    c.colour(col);
    cairo_rectangle(cr, x, y - 11, 22, 12);
    cairo_fill(cr);
    c.colour({0, 0, 0});
    c.text(x + 30, y, label, 13);
    y += 20;
  };
  for (WallMaterial m : materials)
    swatch(material_colour(m), m == WallMaterial::kWoodDoor ? "closed door (wood)" : to_string(m));
  y += 8;
  c.colour({0, 0, 0});
  c.text(x, y, "plan", 14, true);
  y += 22;
  swatch(kFreeSpace, "corridor / hall");
  if (!plan.rooms.empty()) swatch(kRoom, "room");
  if (std::any_of(plan.doors.begin(), plan.doors.end(), [](const Door& d) { return d.open; }))
    swatch(kOpenDoor, "open door");
  if (options.draw_lights && !plan.lights.empty()) swatch(kLight, "ceiling light");
  if (!options.access_points_m.empty()) swatch(kAp, "access point");
  if (options.draw_route) {
    swatch(kRoute, "route (arrows: direction)");
    swatch({0.1, 0.7, 0.2}, "route start");
  }
}

}  // namespace

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
  const int width = static_cast<int>(std::ceil(2 * kMarginPx + extent.x() * ppm + kLegendPx));
  const int height = static_cast<int>(std::ceil(kTitlePx + extent.y() * ppm + 50 + kMarginPx));
  const bool svg = path.extension() == ".svg";
  const std::filesystem::path partial = path.string() + ".partial";

  cairo_surface_t* surface = svg ? cairo_svg_surface_create(partial.c_str(), width, height)
                                 : cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface_guard(
      surface, &cairo_surface_destroy);
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS)
    throw IoError(path.string() + ": cannot create drawing surface: " +
                  cairo_status_to_string(cairo_surface_status(surface)));
  cairo_t* cr = cairo_create(surface);
  std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr_guard(cr, &cairo_destroy);

  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  const Canvas canvas(cr, lo, hi, ppm);

  canvas.fill_regions(plan.free_space, kFreeSpace);
  for (const Room& r : plan.rooms) {
    canvas.ring_path(r.polygon_m);
    canvas.colour(kRoom);
    cairo_fill(cr);
  }
  draw_walls(canvas, plan, plan.wall_thickness_m);
  draw_doors(canvas, plan);
  if (options.draw_lights) {
    for (const CeilingLight& l : plan.lights) {
      const Eigen::Vector2d a = canvas.px(l.center_m.head<2>() - 0.5 * l.size_m);
      const Eigen::Vector2d b = canvas.px(l.center_m.head<2>() + 0.5 * l.size_m);
      cairo_rectangle(cr, a.x(), b.y(), b.x() - a.x(), a.y() - b.y());
      canvas.colour(kLight);
      cairo_fill_preserve(cr);
      canvas.colour({0.6, 0.5, 0.0});
      cairo_set_line_width(cr, 0.8);
      cairo_stroke(cr);
    }
  }
  if (options.draw_route) draw_route(canvas, world.route);
  for (const auto& ap : options.access_points_m) {
    const Eigen::Vector2d p = canvas.px(ap.head<2>());
    cairo_arc(cr, p.x(), p.y(), 5.0, 0, 2 * M_PI);
    canvas.colour(kAp);
    cairo_fill_preserve(cr);
    canvas.colour({1, 1, 1});
    cairo_set_line_width(cr, 1.5);
    cairo_stroke(cr);
  }

  canvas.colour({0, 0, 0});
  canvas.text(kMarginPx, 28, options.title, 20, true);
  draw_scale_bar(canvas, extent.x(), kTitlePx + extent.y() * ppm + 30);
  draw_legend(canvas, plan, options, kMarginPx * 2 + extent.x() * ppm, kTitlePx + 10);

  cairo_destroy(cr_guard.release());
  cairo_status_t status = CAIRO_STATUS_SUCCESS;
  if (svg) {
    cairo_surface_finish(surface);
    status = cairo_surface_status(surface);
  } else {
    status = cairo_surface_write_to_png(surface, partial.c_str());
  }
  if (status != CAIRO_STATUS_SUCCESS) {
    std::error_code ec;
    std::filesystem::remove(partial, ec);
    throw IoError(path.string() +
                  ": cannot write the plan picture: " + cairo_status_to_string(status));
  }
  std::error_code ec;
  std::filesystem::rename(partial, path, ec);
  if (ec) {
    std::filesystem::remove(partial, ec);
    throw IoError(path.string() + ": cannot rename the finished picture into place");
  }
}

}  // namespace wifislam::sim
