#pragma once
// Image files of RGB-D frames. Depth follows the TUM RGB-D convention: 16-bit PNG, 5000 units
// per metre, 0 = no reading (its conversions: core/depth_png.hpp). Writes are atomic
// (core/atomic_file.hpp) and the PNG bytes depend only on the pixels (core/png_codec.hpp), so
// equal frames give byte-identical files.

#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/depth_png.hpp"

namespace wifislam::sim::render {

/// Writes a colour image (CV_8UC3, BGR) as PNG.
void write_color_png(const std::filesystem::path& path, const cv::Mat& color_bgr);
/// Writes depth (CV_32FC1 metres) as a TUM 16-bit depth PNG.
void write_depth_png(const std::filesystem::path& path, const cv::Mat& depth_m);
/// Reads a TUM depth PNG into metres. Throws IoError when the file is missing or not 16-bit,
/// ParseError when it is not a readable PNG.
cv::Mat read_depth_png(const std::filesystem::path& path);

/// Depth for people to look at: a colour map from near (`min_m`, red) to far (`max_m`, blue),
/// black where there is no reading.
cv::Mat depth_false_color(const cv::Mat& depth_m, double min_m, double max_m);
void write_depth_false_color_png(const std::filesystem::path& path, const cv::Mat& depth_m,
                                 double min_m, double max_m);

}  // namespace wifislam::sim::render
