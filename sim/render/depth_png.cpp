#include "sim/render/depth_png.hpp"

#include <cmath>

#include <fmt/core.h>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "core/png_codec.hpp"

namespace wifislam::sim::render {

void write_color_png(const std::filesystem::path& path, const cv::Mat& color_bgr) {
  CV_Assert(color_bgr.type() == CV_8UC3);
  write_png(path, color_bgr);
}

void write_depth_png(const std::filesystem::path& path, const cv::Mat& depth_m) {
  write_png(path, depth_to_png_units(depth_m));
}

cv::Mat read_depth_png(const std::filesystem::path& path) {
  const cv::Mat units = read_png(path);
  if (units.type() != CV_16UC1) {
    throw IoError(
        fmt::format("{}: a depth image must be a 16-bit single-channel PNG (TUM, 5000 "
                    "units per metre)",
                    path.string()));
  }
  return depth_from_png_units(units);
}

cv::Mat depth_false_color(const cv::Mat& depth_m, double min_m, double max_m) {
  CV_Assert(depth_m.type() == CV_32FC1 && max_m > min_m);
  cv::Mat scaled(depth_m.size(), CV_8UC1);
  for (int y = 0; y < depth_m.rows; ++y) {
    const float* in = depth_m.ptr<float>(y);
    auto* out = scaled.ptr<unsigned char>(y);
    for (int x = 0; x < depth_m.cols; ++x) {
      const double t = (in[x] - min_m) / (max_m - min_m);
      out[x] = cv::saturate_cast<unsigned char>(255.0 * (1.0 - std::clamp(t, 0.0, 1.0)));
    }
  }
  cv::Mat colored;
  cv::applyColorMap(scaled, colored, cv::COLORMAP_TURBO);
  colored.setTo(cv::Scalar(0, 0, 0), depth_m <= 0.0f);
  return colored;
}

void write_depth_false_color_png(const std::filesystem::path& path, const cv::Mat& depth_m,
                                 double min_m, double max_m) {
  write_png(path, depth_false_color(depth_m, min_m, max_m));
}

}  // namespace wifislam::sim::render
