// plot/canvas: the metres -> pixels mapping every plan-shaped figure uses, and figure files
// written through real cairo surfaces and read back with OpenCV.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/core/mat.hpp>

#include "core/error.hpp"
#include "core/png_codec.hpp"
#include "plot/canvas.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::plot {
namespace {

namespace fs = std::filesystem;

/// A file of that name in a scratch folder of its own (a second call in one test would empty a
/// shared one).
fs::path scratch(const std::string& name) { return test::scratch_folder(name) / name; }

TEST(MetricCanvas, NorthIsUpAndOneMetreIsPpmPixels) {
  const MetricCanvas canvas = MetricCanvas::exact({0, 0}, {10, 5}, 20.0);
  const Eigen::Vector2d origin = canvas.px({0, 0});
  EXPECT_DOUBLE_EQ(origin.x(), MetricCanvas::kMarginPx);
  EXPECT_DOUBLE_EQ(origin.y(), MetricCanvas::kTitlePx + 5 * 20.0);  // y = 0 is the plan's bottom
  const Eigen::Vector2d east = canvas.px({1, 0}) - origin;
  const Eigen::Vector2d north = canvas.px({0, 1}) - origin;
  EXPECT_DOUBLE_EQ(east.x(), 20.0);
  EXPECT_DOUBLE_EQ(east.y(), 0.0);
  EXPECT_DOUBLE_EQ(north.y(), -20.0);  // north goes up the image
  EXPECT_DOUBLE_EQ(canvas.plan_right_px(), MetricCanvas::kMarginPx + 200.0);
  EXPECT_DOUBLE_EQ(canvas.plan_bottom_px(), MetricCanvas::kTitlePx + 100.0);
}

TEST(MetricCanvas, LayoutPadsHalfAMetreAndClampsThePixelsPerMetre) {
  // 20 m x 10 m padded to 21 m x 11 m, the long side about 840 px: 40 px a metre.
  const MetricCanvas canvas({0, 0}, {20, 10}, 840.0);
  EXPECT_DOUBLE_EQ(canvas.ppm(), 40.0);
  EXPECT_DOUBLE_EQ(canvas.plan_width_m(), 21.0);
  EXPECT_NEAR(canvas.px({-0.5, 0}).x(), MetricCanvas::kMarginPx, 1e-9);
  EXPECT_EQ(canvas.width_px(),
            static_cast<int>(std::ceil(MetricCanvas::kMarginPx + 21 * 40.0 +
                                       MetricCanvas::kMarginPx + MetricCanvas::kLegendPx)));
  // A huge building gets at least 2 px a metre; a point at most 120.
  EXPECT_DOUBLE_EQ(MetricCanvas({0, 0}, {10000, 10}, 800.0).ppm(), 2.0);
  EXPECT_DOUBLE_EQ(MetricCanvas({0, 0}, {0, 0}, 800.0).ppm(), 120.0);
  EXPECT_GE(MetricCanvas({0, 0}, {0, 0}, 800.0).height_px(), 360);
}

TEST(WriteFigure, WritesThePixelsDrawnAtomically) {
  const fs::path png = scratch("square.png");
  write_figure(png, 40, 30, [](cairo_t* cr) {
    set_colour(cr, Colour{1.0, 0.0, 0.0});
    cairo_rectangle(cr, 10, 10, 10, 10);
    cairo_fill(cr);
  });
  EXPECT_FALSE(fs::exists(png.string() + ".partial"));
  const cv::Mat image = read_png(png);
  ASSERT_EQ(image.cols, 40);
  ASSERT_EQ(image.rows, 30);
  ASSERT_EQ(image.depth(), CV_8U);
  ASSERT_GE(image.channels(), 3);  // cairo writes colour, with alpha or without
  const auto bgr = [&](int y, int x) {
    const std::uint8_t* p = image.ptr<std::uint8_t>(y) + x * image.channels();
    return cv::Vec3b(p[0], p[1], p[2]);
  };
  EXPECT_EQ(bgr(15, 15), cv::Vec3b(0, 0, 255));    // red, in BGR
  EXPECT_EQ(bgr(2, 2), cv::Vec3b(255, 255, 255));  // painted white first
  fs::remove_all(png.parent_path());
}

TEST(WriteFigure, SvgByItsNameAndAnUnwritablePathIsAnIoError) {
  const fs::path svg = scratch("figure.svg");
  write_figure(svg, 20, 20, [](cairo_t*) {});
  std::ifstream in(svg);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_THROW(write_figure(svg.parent_path() / "no" / "such" / "dir.png", 10, 10, [](cairo_t*) {}),
               IoError);
  fs::remove_all(svg.parent_path());
}

TEST(Colours, CategoriesDifferAndViridisRunsDarkToLight) {
  const Colour a = category_colour(0), b = category_colour(1);
  EXPECT_FALSE(a.r == b.r && a.g == b.g && a.b == b.b);
  const Colour lo = viridis(0.0), hi = viridis(1.0);
  EXPECT_LT(lo.r + lo.g + lo.b, hi.r + hi.g + hi.b);
}

}  // namespace
}  // namespace wifislam::plot
