#include "sim/render/procedural_textures.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/core.h>
#include <fmt/ranges.h>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "core/rng.hpp"

namespace wifislam::sim::render {

namespace {

cv::Scalar rgb(double r, double g, double b) { return cv::Scalar(b, g, r); }

cv::Scalar jitter(const cv::Scalar& colour, double amount, Rng& rng) {
  cv::Scalar out;
  const double common = rng.uniform(-amount, amount);
  for (int c = 0; c < 3; ++c) {
    out[c] = std::clamp(colour[c] + common + rng.uniform(-amount, amount) * 0.5, 0.0, 255.0);
  }
  return out;
}

cv::Scalar scaled(const cv::Scalar& colour, double factor) {
  return cv::Scalar(std::min(255.0, colour[0] * factor), std::min(255.0, colour[1] * factor),
                    std::min(255.0, colour[2] * factor));
}

cv::Scalar pick(const std::vector<cv::Scalar>& palette, Rng& rng) {
  return palette[static_cast<std::size_t>(
      rng.uniform_int(0, static_cast<int>(palette.size()) - 1))];
}

// Smooth value noise in [-1, 1] that wraps around both image edges. Written here because
// cv::resize has no periodic border, and tiling textures must not show seams.
cv::Mat periodic_noise(int width, int height, int cells_x, int cells_y, Rng& rng) {
  std::vector<float> grid(static_cast<std::size_t>(cells_x * cells_y));
  for (float& value : grid) value = static_cast<float>(rng.uniform(-1.0, 1.0));
  cv::Mat out(height, width, CV_32F);
  for (int y = 0; y < height; ++y) {
    const double fy = static_cast<double>(y) * cells_y / height;
    const int y0 = static_cast<int>(fy) % cells_y, y1 = (y0 + 1) % cells_y;
    double ty = fy - std::floor(fy);
    ty = ty * ty * (3 - 2 * ty);
    auto* row = out.ptr<float>(y);
    for (int x = 0; x < width; ++x) {
      const double fx = static_cast<double>(x) * cells_x / width;
      const int x0 = static_cast<int>(fx) % cells_x, x1 = (x0 + 1) % cells_x;
      double tx = fx - std::floor(fx);
      tx = tx * tx * (3 - 2 * tx);
      const double top = grid[y0 * cells_x + x0] * (1 - tx) + grid[y0 * cells_x + x1] * tx;
      const double bottom = grid[y1 * cells_x + x0] * (1 - tx) + grid[y1 * cells_x + x1] * tx;
      row[x] = static_cast<float>(top * (1 - ty) + bottom * ty);
    }
  }
  return out;
}

// Adds `amplitude` x noise (same for all channels: a brightness variation) to a BGR image.
void add_brightness(cv::Mat& bgr, const cv::Mat& noise, double amplitude) {
  for (int y = 0; y < bgr.rows; ++y) {
    auto* px = bgr.ptr<cv::Vec3b>(y);
    const auto* n = noise.ptr<float>(y);
    for (int x = 0; x < bgr.cols; ++x) {
      const double delta = amplitude * n[x];
      for (int c = 0; c < 3; ++c) px[x][c] = cv::saturate_cast<uchar>(px[x][c] + delta);
    }
  }
}

// Per-pixel grain (paint, concrete): independent uniform brightness noise.
void add_grain(cv::Mat& bgr, double amplitude, Rng& rng) {
  cv::Mat noise(bgr.rows, bgr.cols, CV_32F);
  for (int y = 0; y < noise.rows; ++y) {
    auto* row = noise.ptr<float>(y);
    for (int x = 0; x < noise.cols; ++x) row[x] = static_cast<float>(rng.uniform(-1.0, 1.0));
  }
  add_brightness(bgr, noise, amplitude);
}

cv::Point point_m(double u_m, double v_from_top_m, double px_per_m) {
  return {static_cast<int>(std::lround(u_m * px_per_m)),
          static_cast<int>(std::lround(v_from_top_m * px_per_m))};
}

// Rows of dark "words" of random widths: reads as printed text to a feature detector.
void draw_text_lines(cv::Mat& img, cv::Rect area, int line_height_px, const cv::Scalar& ink,
                     Rng& rng) {
  for (int y = area.y; y + line_height_px <= area.y + area.height; y += line_height_px * 2) {
    int x = area.x;
    const int line_end = area.x + static_cast<int>(area.width * rng.uniform(0.6, 1.0));
    while (x < line_end) {
      const int word = static_cast<int>(rng.uniform(1.5, 6.0) * line_height_px);
      const int end = std::min(x + word, line_end);
      if (end - x >= 2)
        cv::rectangle(img, {x, y}, {end - 1, y + line_height_px - 1}, ink, cv::FILLED);
      x = end + line_height_px;
    }
  }
}

std::string random_word(Rng& rng, int min_letters, int max_letters) {
  std::string word;
  const auto n = rng.uniform_int(min_letters, max_letters);
  for (int i = 0; i < n; ++i) word.push_back(static_cast<char>('A' + rng.uniform_int(0, 25)));
  return word;
}

// Things found on corridor walls: switch plates, room signs, notice boards, exit signs, scuffs.
// They are what makes one wall segment distinguishable from another.
void draw_wall_markings(cv::Mat& img, double width_m, double height_m, double px_per_m,
                        const cv::Scalar& paint, Rng& rng) {
  const int count = static_cast<int>(rng.uniform_int(3, 6));
  for (int i = 0; i < count; ++i) {
    const int type = static_cast<int>(rng.uniform_int(0, 4));
    const double u = rng.uniform(0.3, width_m - 0.9);
    switch (type) {
      case 0: {  // switch or socket plate
        const double v = height_m - rng.uniform(0.3, 1.3);
        const cv::Point a = point_m(u, v, px_per_m), b = point_m(u + 0.09, v + 0.13, px_per_m);
        cv::rectangle(img, a, b, rgb(238, 238, 232), cv::FILLED);
        cv::rectangle(img, a, b, rgb(120, 120, 118), 1);
        cv::rectangle(img, point_m(u + 0.03, v + 0.04, px_per_m),
                      point_m(u + 0.06, v + 0.09, px_per_m), rgb(90, 90, 90), cv::FILLED);
        break;
      }
      case 1: {  // room or department sign with text
        const double v = height_m - rng.uniform(1.5, 1.8);
        const double w = rng.uniform(0.25, 0.45), h = rng.uniform(0.1, 0.16);
        const cv::Scalar plate =
            pick({rgb(40, 60, 120), rgb(30, 30, 35), rgb(200, 200, 205), rgb(20, 100, 70)}, rng);
        const cv::Scalar ink =
            (plate[0] + plate[1] + plate[2] > 300) ? rgb(20, 20, 20) : rgb(245, 245, 245);
        const cv::Point a = point_m(u, v, px_per_m), b = point_m(u + w, v + h, px_per_m);
        cv::rectangle(img, a, b, plate, cv::FILLED);
        cv::putText(img, random_word(rng, 2, 4), {a.x + 3, b.y - 4}, cv::FONT_HERSHEY_SIMPLEX,
                    (b.y - a.y) / 30.0, ink, 1, cv::LINE_AA);
        break;
      }
      case 2: {  // notice board with pinned sheets
        const double v = height_m - rng.uniform(1.2, 1.9);
        const double w = rng.uniform(0.5, 0.8), h = rng.uniform(0.4, 0.6);
        const cv::Point a = point_m(u, v, px_per_m), b = point_m(u + w, v + h, px_per_m);
        cv::rectangle(img, a, b, rgb(176, 132, 84), cv::FILLED);
        cv::rectangle(img, a, b, rgb(90, 70, 50), 2);
        const int sheets = static_cast<int>(rng.uniform_int(2, 5));
        for (int s = 0; s < sheets; ++s) {
          const double su = u + rng.uniform(0.03, w - 0.2), sv = v + rng.uniform(0.03, h - 0.22);
          const cv::Point sa = point_m(su, sv, px_per_m),
                          sb = point_m(su + 0.15, sv + 0.2, px_per_m);
          cv::rectangle(img, sa, sb,
                        pick({rgb(250, 250, 245), rgb(250, 240, 150), rgb(200, 230, 250)}, rng),
                        cv::FILLED);
          draw_text_lines(img, cv::Rect(sa.x + 2, sa.y + 3, sb.x - sa.x - 4, sb.y - sa.y - 6), 2,
                          rgb(60, 60, 70), rng);
        }
        break;
      }
      case 3: {  // exit sign: green plate with a white pictogram
        const double v = height_m - rng.uniform(2.0, 2.2);
        const cv::Point a = point_m(u, v, px_per_m), b = point_m(u + 0.3, v + 0.15, px_per_m);
        cv::rectangle(img, a, b, rgb(20, 150, 70), cv::FILLED);
        const int h = b.y - a.y;
        cv::circle(img, {a.x + h / 2, a.y + h / 4}, std::max(1, h / 8), rgb(250, 250, 250),
                   cv::FILLED);
        cv::rectangle(img, {a.x + h / 3, a.y + h / 3}, {a.x + 2 * h / 3, a.y + 4 * h / 5},
                      rgb(250, 250, 250), cv::FILLED);
        cv::arrowedLine(img, {a.x + h, a.y + h / 2}, {b.x - 4, a.y + h / 2}, rgb(250, 250, 250), 2);
        break;
      }
      default: {  // scuff mark
        const double v = height_m - rng.uniform(0.15, 0.9);
        // A darker smudge blended into the paint around it only.
        const cv::Point centre = point_m(u, v, px_per_m);
        const cv::Size axes(static_cast<int>(rng.uniform(0.05, 0.2) * px_per_m),
                            static_cast<int>(rng.uniform(0.01, 0.04) * px_per_m));
        const double angle_deg = rng.uniform(-20, 20);
        const int reach = axes.width + 4;
        const cv::Rect roi = cv::Rect(centre.x - reach, centre.y - reach, 2 * reach, 2 * reach) &
                             cv::Rect(0, 0, img.cols, img.rows);
        cv::Mat mask(roi.size(), CV_32F, cv::Scalar(0));
        cv::ellipse(mask, centre - roi.tl(), axes, angle_deg, 0, 360, cv::Scalar(0.6), cv::FILLED);
        cv::GaussianBlur(mask, mask, cv::Size(5, 5), 0);
        const cv::Scalar dark = scaled(paint, 0.75);
        for (int y = 0; y < roi.height; ++y) {
          auto* px = img.ptr<cv::Vec3b>(roi.y + y) + roi.x;
          const auto* m = mask.ptr<float>(y);
          for (int x = 0; x < roi.width; ++x) {
            for (int c = 0; c < 3; ++c) {
              px[x][c] = cv::saturate_cast<uchar>(px[x][c] * (1.0f - m[x]) + dark[c] * m[x]);
            }
          }
        }
        break;
      }
    }
  }
}

const std::vector<cv::Scalar>& paint_palette() {
  static const std::vector<cv::Scalar> palette = {rgb(228, 224, 214), rgb(212, 220, 228),
                                                  rgb(226, 216, 196), rgb(208, 222, 206),
                                                  rgb(232, 212, 200), rgb(220, 220, 222)};
  return palette;
}

constexpr double kWallPeriodM = 4.0;  // one wall image spans a default appearance segment
constexpr int kWallSizePx = 512;

TextureImage make_wall(const std::string& theme, Rng& rng) {
  TextureImage t;
  t.period_u_m = t.period_v_m = kWallPeriodM;
  const double px_per_m = kWallSizePx / kWallPeriodM;
  const cv::Scalar paint = jitter(pick(paint_palette(), rng), 6.0, rng);
  t.bgr = cv::Mat(kWallSizePx, kWallSizePx, CV_8UC3, paint);
  if (theme == "brick") {
    const cv::Scalar brick = jitter(rgb(160, 82, 60), 15.0, rng);
    const int brick_w = static_cast<int>(0.25 * px_per_m),
              brick_h = static_cast<int>(0.0625 * px_per_m);
    t.bgr.setTo(rgb(190, 185, 175));
    for (int row = 0; row * brick_h < kWallSizePx; ++row) {
      const int offset = (row % 2) * brick_w / 2;
      for (int x = -offset; x < kWallSizePx; x += brick_w) {
        cv::rectangle(t.bgr, {x + 1, row * brick_h + 1},
                      {x + brick_w - 2, row * brick_h + brick_h - 2}, jitter(brick, 12.0, rng),
                      cv::FILLED);
      }
    }
    add_grain(t.bgr, 6.0, rng);
  } else {
    add_brightness(t.bgr, periodic_noise(kWallSizePx, kWallSizePx, 8, 8, rng), 5.0);
    add_grain(t.bgr, 3.0, rng);
  }
  // Dado rail on some walls, at a height of its own.
  if (rng.bernoulli(0.5)) {
    const double v = kWallPeriodM - rng.uniform(0.9, 1.1);
    cv::rectangle(t.bgr, point_m(0, v, px_per_m), point_m(kWallPeriodM, v + 0.03, px_per_m),
                  scaled(paint, 0.7), cv::FILLED);
  }
  draw_wall_markings(t.bgr, kWallPeriodM, kWallPeriodM, px_per_m, paint, rng);
  // Skirting board along the floor.
  cv::rectangle(t.bgr, point_m(0, kWallPeriodM - 0.1, px_per_m),
                point_m(kWallPeriodM, kWallPeriodM, px_per_m), rgb(85, 78, 70), cv::FILLED);
  return t;
}

// Floors and ceilings repeat with a long period: with a short one (a 2 m terrazzo tile, say) the
// speckles ORB locks onto repeat every couple of metres, and every corridor aliases with itself
// at that spacing whatever the walls look like. 12 m (floor) and 9.6 m (ceiling) keep look-alike
// floor patches as far apart as a corridor, at the same texel size as before (128 / 213 px/m).
constexpr double kFloorPeriodM = 12.0;
constexpr int kFloorSizePx = 1536;
constexpr double kCeilingPeriodM = 9.6;
constexpr int kCeilingSizePx = 2048;

TextureImage make_floor(const std::string& theme, Rng& rng) {
  TextureImage t;
  t.period_u_m = t.period_v_m = kFloorPeriodM;
  constexpr int size = kFloorSizePx;
  constexpr int metres = static_cast<int>(kFloorPeriodM);
  if (theme == "carpet") {
    const cv::Scalar base =
        jitter(pick({rgb(90, 95, 110), rgb(110, 80, 70), rgb(80, 100, 85)}, rng), 8, rng);
    t.bgr = cv::Mat(size, size, CV_8UC3, base);
    add_brightness(t.bgr, periodic_noise(size, size, 16 * metres, 16 * metres, rng), 10.0);
    add_grain(t.bgr, 14.0, rng);
    return t;
  }
  const cv::Scalar base =
      jitter(pick({rgb(200, 196, 186), rgb(180, 182, 186), rgb(196, 184, 166)}, rng), 8, rng);
  t.bgr = cv::Mat(size, size, CV_8UC3, rgb(110, 108, 104));  // grout
  constexpr int tiles = 2 * metres;                          // 0.5 m tiles
  const int tile = size / tiles;
  for (int ty = 0; ty < tiles; ++ty) {
    for (int tx = 0; tx < tiles; ++tx) {
      cv::rectangle(t.bgr, {tx * tile + 1, ty * tile + 1},
                    {tx * tile + tile - 2, ty * tile + tile - 2}, jitter(base, 6.0, rng),
                    cv::FILLED);
    }
  }
  add_brightness(t.bgr, periodic_noise(size, size, 8 * metres, 8 * metres, rng), 6.0);
  for (int i = 0; i < 100 * metres * metres; ++i) {  // terrazzo speckles, 100 per m^2
    const cv::Point p(static_cast<int>(rng.uniform_int(0, size - 1)),
                      static_cast<int>(rng.uniform_int(0, size - 1)));
    cv::circle(t.bgr, p, 1, scaled(base, rng.uniform(0.5, 0.85)), cv::FILLED);
  }
  return t;
}

TextureImage make_ceiling(const std::string& theme, Rng& rng) {
  TextureImage t;
  t.period_u_m = t.period_v_m = kCeilingPeriodM;
  constexpr int size = kCeilingSizePx;
  constexpr int panels = static_cast<int>(kCeilingPeriodM / 0.6 + 0.5);  // 0.6 m panels
  const cv::Scalar base = jitter(rgb(236, 236, 230), 4.0, rng);
  t.bgr = cv::Mat(size, size, CV_8UC3, base);
  if (theme == "plain") {
    add_brightness(t.bgr, periodic_noise(size, size, 4 * panels, 4 * panels, rng), 4.0);
    add_grain(t.bgr, 2.0, rng);
    return t;
  }
  for (int i = 0; i < 375 * panels * panels; ++i) {  // perforated mineral-fibre panels
    const cv::Point p(static_cast<int>(rng.uniform_int(0, size - 1)),
                      static_cast<int>(rng.uniform_int(0, size - 1)));
    cv::circle(t.bgr, p, 0, scaled(base, 0.8), cv::FILLED);
  }
  const int panel = size / panels;  // in a metal grid
  for (int k = 0; k < panels; ++k) {
    cv::rectangle(t.bgr, {k * panel, 0}, {k * panel + 2, size - 1}, rgb(175, 175, 172), cv::FILLED);
    cv::rectangle(t.bgr, {0, k * panel}, {size - 1, k * panel + 2}, rgb(175, 175, 172), cv::FILLED);
  }
  return t;
}

TextureImage make_door(const std::string& theme, Rng& rng) {
  TextureImage t;
  t.fit_to_face = true;
  constexpr int w = 256, h = 512;
  if (theme == "painted") {
    t.bgr = cv::Mat(
        h, w, CV_8UC3,
        jitter(pick({rgb(70, 90, 140), rgb(230, 230, 225), rgb(150, 40, 40)}, rng), 10, rng));
    add_grain(t.bgr, 3.0, rng);
  } else {
    const cv::Scalar wood =
        jitter(pick({rgb(150, 100, 60), rgb(185, 140, 90), rgb(120, 75, 45)}, rng), 10, rng);
    t.bgr = cv::Mat(h, w, CV_8UC3, wood);
    add_brightness(t.bgr, periodic_noise(w, h, 40, 3, rng), 16.0);  // long vertical grain
    add_grain(t.bgr, 4.0, rng);
  }
  const cv::Scalar base = t.bgr.at<cv::Vec3b>(h / 2, w / 2);
  // Two recessed panels, a handle and a kick plate: the corners a detector picks up on doors.
  const int panels = static_cast<int>(rng.uniform_int(1, 2));
  const int top = h / 12, bottom = h - h / 6, gap = h / 16;
  const int panel_h = (bottom - top - (panels - 1) * gap) / panels;
  for (int p = 0; p < panels; ++p) {
    const cv::Rect panel(w / 6, top + p * (panel_h + gap), w * 2 / 3, panel_h);
    cv::rectangle(t.bgr, panel, scaled(base, 0.7), 3);
    cv::rectangle(t.bgr, panel + cv::Point(3, 3), scaled(base, 1.15), 1);
  }
  const int handle_y = static_cast<int>(h * rng.uniform(0.47, 0.53));
  cv::rectangle(t.bgr, {w - w / 6 - 8, handle_y - 22}, {w - w / 6 + 4, handle_y + 22},
                rgb(170, 170, 175), cv::FILLED);
  cv::rectangle(t.bgr, {w - w / 6 - 40, handle_y - 5}, {w - w / 6 + 4, handle_y + 5},
                rgb(205, 205, 210), cv::FILLED);
  if (rng.bernoulli(0.6)) {
    cv::rectangle(t.bgr, {4, h - h / 14}, {w - 5, h - 4}, rgb(160, 160, 165), cv::FILLED);
  }
  return t;
}

TextureImage make_poster(Rng& rng) {
  TextureImage t;
  t.fit_to_face = true;
  constexpr int size = 256;
  const cv::Scalar paper = jitter(pick({rgb(245, 243, 235), rgb(250, 230, 160), rgb(30, 40, 70),
                                        rgb(210, 230, 245), rgb(240, 200, 200)},
                                       rng),
                                  8, rng);
  const bool dark = paper[0] + paper[1] + paper[2] < 300;
  const cv::Scalar ink = dark ? rgb(240, 240, 240) : rgb(25, 25, 35);
  t.bgr = cv::Mat(size, size, CV_8UC3, paper);
  const std::vector<cv::Scalar> accents = {rgb(200, 40, 40), rgb(30, 90, 190),  rgb(240, 170, 20),
                                           rgb(40, 150, 80), rgb(120, 50, 150), rgb(20, 20, 20)};
  // Title in large letters.
  cv::putText(t.bgr, random_word(rng, 3, 6), {14, 48},
              static_cast<int>(rng.uniform_int(0, 1)) == 0 ? cv::FONT_HERSHEY_DUPLEX
                                                           : cv::FONT_HERSHEY_TRIPLEX,
              rng.uniform(1.1, 1.5), pick(accents, rng), 3, cv::LINE_AA);
  // Graphic: a few bold shapes.
  const int shapes = static_cast<int>(rng.uniform_int(2, 5));
  for (int i = 0; i < shapes; ++i) {
    const cv::Point c(static_cast<int>(rng.uniform(40, 216)),
                      static_cast<int>(rng.uniform(80, 170)));
    const int r = static_cast<int>(rng.uniform(12, 40));
    const cv::Scalar colour = pick(accents, rng);
    switch (rng.uniform_int(0, 2)) {
      case 0:
        cv::circle(t.bgr, c, r, colour, cv::FILLED, cv::LINE_AA);
        break;
      case 1:
        cv::rectangle(t.bgr, c - cv::Point(r, r / 2), c + cv::Point(r, r / 2), colour, cv::FILLED);
        break;
      default: {
        const std::vector<cv::Point> tri = {c + cv::Point(0, -r), c + cv::Point(r, r),
                                            c + cv::Point(-r, r)};
        cv::fillConvexPoly(t.bgr, tri, colour, cv::LINE_AA);
      }
    }
  }
  draw_text_lines(t.bgr, cv::Rect(16, 190, size - 32, 52), 5, ink, rng);
  cv::rectangle(t.bgr, {0, 0}, {size - 1, size - 1}, ink, 4);
  return t;
}

TextureImage make_plain(const cv::Scalar& colour, double period_m, double grain, Rng& rng) {
  TextureImage t;
  t.period_u_m = t.period_v_m = period_m;
  t.bgr = cv::Mat(64, 64, CV_8UC3, colour);
  add_grain(t.bgr, grain, rng);
  return t;
}

TextureImage make_light() {
  TextureImage t;
  t.fit_to_face = true;
  t.emissive = true;
  constexpr int size = 64;
  t.bgr = cv::Mat(size, size, CV_8UC3, rgb(255, 255, 250));
  for (int k = 1; k < 4; ++k) {  // louvre grid
    cv::line(t.bgr, {k * size / 4, 0}, {k * size / 4, size - 1}, rgb(215, 215, 210), 2);
    cv::line(t.bgr, {0, k * size / 4}, {size - 1, k * size / 4}, rgb(215, 215, 210), 2);
  }
  cv::rectangle(t.bgr, {0, 0}, {size - 1, size - 1}, rgb(150, 150, 150), 3);
  return t;
}

void check_theme(const std::string& what, const std::string& name,
                 const std::vector<std::string>& known) {
  if (std::find(known.begin(), known.end(), name) == known.end()) {
    throw InvalidInputError(fmt::format("appearance.themes.{}: unknown theme '{}' (known: {})",
                                        what, name, fmt::join(known, ", ")));
  }
}

}  // namespace

TextureKey texture_key_of(const world::Triangle& triangle) {
  switch (triangle.surface) {
    case world::SurfaceKind::kPoster:
      return {triangle.surface, triangle.appearance_variant, triangle.decoration};
    case world::SurfaceKind::kLight:
    case world::SurfaceKind::kWallTop:
      return {triangle.surface, 0, -1};
    default:
      return {triangle.surface, triangle.appearance_variant, -1};
  }
}

const std::vector<std::string>& ProceduralTextures::wall_themes() {
  static const std::vector<std::string> names = {"painted", "brick"};
  return names;
}
const std::vector<std::string>& ProceduralTextures::door_themes() {
  static const std::vector<std::string> names = {"wood", "painted"};
  return names;
}
const std::vector<std::string>& ProceduralTextures::floor_themes() {
  static const std::vector<std::string> names = {"tiles", "carpet"};
  return names;
}
const std::vector<std::string>& ProceduralTextures::ceiling_themes() {
  static const std::vector<std::string> names = {"panels", "plain"};
  return names;
}

ProceduralTextures::ProceduralTextures(std::uint64_t seed, const scene::AppearanceThemes& themes)
    : seed_(seed), themes_(themes) {
  check_theme("wall", themes.wall, wall_themes());
  check_theme("door", themes.door, door_themes());
  check_theme("floor", themes.floor, floor_themes());
  check_theme("ceiling", themes.ceiling, ceiling_themes());
}

TextureImage ProceduralTextures::make(const TextureKey& key) const {
  auto stream = [&](const std::string& what) {
    return Rng::stream(seed_, fmt::format("texture/{}/v{}/d{}", what, key.variant, key.decoration));
  };
  switch (key.surface) {
    case world::SurfaceKind::kWall: {
      Rng rng = stream("wall/" + themes_.wall);
      return make_wall(themes_.wall, rng);
    }
    case world::SurfaceKind::kFloor: {
      Rng rng = stream("floor/" + themes_.floor);
      return make_floor(themes_.floor, rng);
    }
    case world::SurfaceKind::kCeiling: {
      Rng rng = stream("ceiling/" + themes_.ceiling);
      return make_ceiling(themes_.ceiling, rng);
    }
    case world::SurfaceKind::kDoor: {
      Rng rng = stream("door/" + themes_.door);
      return make_door(themes_.door, rng);
    }
    case world::SurfaceKind::kPoster: {
      Rng rng = stream("poster");
      return make_poster(rng);
    }
    case world::SurfaceKind::kDoorFrame: {
      Rng rng = stream("door_frame");
      return make_plain(jitter(rgb(120, 112, 104), 10.0, rng), 1.0, 4.0, rng);
    }
    case world::SurfaceKind::kLight:
      return make_light();
    case world::SurfaceKind::kWallTop:
    default: {
      Rng rng = stream("wall_top");
      return make_plain(rgb(150, 150, 150), 1.0, 3.0, rng);
    }
  }
}

}  // namespace wifislam::sim::render
