#pragma once
// Writes an image as a PNG file with the codec every dataset uses (core/png_codec.hpp), for tests
// that plant images in a dataset folder.

#include <filesystem>
#include <string_view>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "core/atomic_file.hpp"
#include "core/png_codec.hpp"

namespace wifislam::test {

inline void write_png(const std::filesystem::path& path, const cv::Mat& image) {
  const std::vector<unsigned char> bytes = encode_png(image);
  write_file_atomic(path,
                    std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace wifislam::test
