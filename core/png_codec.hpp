#pragma once
// PNG, the one image format of a dataset (TUM RGB-D: 8-bit colour, 16-bit depth), encoded and
// decoded with libpng directly.
//
// Why not OpenCV's imgcodecs, which calls the same libpng: Debian builds imgcodecs with GDAL, so
// every process that links it loads about 120 more shared libraries before `main` (0.12 s of CPU
// each time, measured: docs/benchmarks.md), and every test process and the Python module did.
// The calls below are the ones OpenCV 4 makes, in the same order and with the same settings, so
// the bytes written and the pixels read are those of cv::imencode(".png") and
// cv::imdecode(..., cv::IMREAD_UNCHANGED); tests/core/png_codec_test.cpp checks both against
// OpenCV itself.

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

namespace wifislam {

/// PNG bytes of an 8-bit or 16-bit image of 1 (grey), 3 (BGR) or 4 (BGRA) channels, as
/// cv::imencode(".png", image) writes them with its default parameters (filter SUB, zlib level 1,
/// Z_RLE): they depend only on the pixels. Throws std::invalid_argument for any other type and
/// IoError if libpng fails.
std::vector<unsigned char> encode_png(const cv::Mat& image);

/// The pixels of PNG bytes as stored, as cv::imdecode(bytes, cv::IMREAD_UNCHANGED) gives them:
/// grey -> CV_8UC1, colour -> CV_8UC3 (BGR), colour with alpha or a transparent colour, and grey
/// with alpha -> CV_8UC4 (BGRA); 16-bit images in 16 bits, palettes expanded. Throws ParseError
/// naming `name` when the bytes are empty, not a PNG, corrupt or truncated, or larger than
/// OpenCV's limits (2^20 pixels a side, 2^30 in all).
cv::Mat decode_png(std::span<const unsigned char> bytes, const std::string& name);

/// encode_png's bytes written to `path` atomically (core/atomic_file.hpp).
void write_png(const std::filesystem::path& path, const cv::Mat& image);

/// decode_png of a file's bytes. Throws IoError when the file cannot be read.
cv::Mat read_png(const std::filesystem::path& path);

}  // namespace wifislam
